#include "gui/diagnosis_panel.hpp"

#include <QHeaderView>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace shadowlab {
namespace {

enum Column { kCause, kPixels, kShare, kColumns };

// The cause's colour in the Error view's causes mode, as a swatch beside its name.
QIcon swatch(const CauseInfo& cause) {
    QPixmap pixmap(14, 14);
    pixmap.fill(QColor(cause.colour[0], cause.colour[1], cause.colour[2]));
    return QIcon(pixmap);
}

QTableWidgetItem* cell(const QString& text, const QString& tip, Qt::Alignment alignment) {
    auto* item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled);
    item->setToolTip(tip);
    item->setTextAlignment(static_cast<int>(alignment | Qt::AlignVCenter));
    return item;
}

// The remedy's run from the inspection and the error it was diagnosed with.
std::optional<Remedy> remedy_of(const CauseInfo& cause, const Inspection& in, const ShadowError& error) {
    if (!cause.remedy) return std::nullopt;
    return cause.remedy({.method = *in.method,
                         .settings = in.settings,
                         .resolution = in.resolution,
                         .bias = in.bias,
                         .m_perspective_p95 = error.m_perspective.p95,
                         .m_p95 = error.m.p95});
}

}  // namespace

InspectionRequest request_for(const Remedy& remedy) {
    InspectionRequest request{.method = remedy.method->name, .resolution = remedy.resolution, .bias = remedy.bias};
    for (const auto& [name, value] : remedy.settings.values())
        request.settings[name] = std::holds_alternative<double>(value)
                                     ? QString::number(std::get<double>(value), 'g', 12).toStdString()
                                     : std::get<std::string>(value);
    return request;
}

DiagnosisPanel::DiagnosisPanel(QWidget* parent)
    : QWidget(parent), summary_(new QLabel(this)), table_(new QTableWidget(0, kColumns, this)) {
    summary_->setObjectName("diagnosisSummary");
    summary_->setWordWrap(true);
    summary_->setText("no inspection yet");
    table_->setObjectName("causes");
    table_->setHorizontalHeaderLabels({"Cause", "Pixels", "Share"});
    table_->verticalHeader()->hide();
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setWordWrap(false);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setSectionResizeMode(kCause, QHeaderView::Stretch);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(summary_);
    layout->addWidget(table_, 1);
}

void DiagnosisPanel::show_diagnosis(const Inspection& inspection, const ShadowError& error) {
    diagnosis_ = count_causes(error);
    summary_->setText(QString("%1 of %2 receiver pixels misclassified (%3 %), by cause:")
                          .arg(diagnosis_.misclassified)
                          .arg(error.receiver_pixels)
                          .arg(100.0 * error.misclassified, 0, 'f', 3));
    table_->clearSpans();
    table_->setRowCount(0);
    for (const CauseCount& cause : diagnosis_.causes) add_rows(cause, remedy_of(info(cause.kind), inspection, error));
}

// The cause's row, and beneath it, across the columns, its remedy's button if it has one.
void DiagnosisPanel::add_rows(const CauseCount& cause, const std::optional<Remedy>& remedy) {
    const CauseInfo& c = info(cause.kind);
    const QString meaning = QString::fromUtf8(c.meaning);
    int row = table_->rowCount();
    table_->insertRow(row);
    QTableWidgetItem* name = cell(c.name, meaning, Qt::AlignLeft);
    name->setIcon(swatch(c));
    table_->setItem(row, kCause, name);
    table_->setItem(row, kPixels, cell(QString::number(cause.pixels), meaning, Qt::AlignRight));
    table_->setItem(row, kShare, cell(QString("%1 %").arg(100.0 * cause.share, 0, 'f', 3), meaning, Qt::AlignRight));
    if (!remedy) return;
    const QString change = QString::fromStdString(remedy->change);
    auto* apply = new QPushButton("Apply: " + change);
    apply->setObjectName(QString("apply_") + c.name);
    apply->setToolTip("compute the run again with " + change + ", the scene, camera and views kept");
    connect(apply, &QPushButton::clicked, this,
            [this, request = request_for(*remedy), change] { emit remedyChosen(request, change); });
    table_->insertRow(++row);
    table_->setSpan(row, 0, 1, kColumns);
    table_->setCellWidget(row, 0, apply);
}

}  // namespace shadowlab
