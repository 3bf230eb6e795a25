#include "gui/step_player.hpp"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>

#include "io/value_text.hpp"

namespace shadowlab {
namespace {

constexpr int kDetailsMinHeight = 120;  // below it a very long trace's list scrolls instead

// A list that asks for the height of all its rows (uniform): the layout gives it that while the dock
// has room, and it scrolls only in a shorter dock.
class StepList : public QListWidget {
public:
    using QListWidget::QListWidget;
    QSize sizeHint() const override {
        const int rows = count() > 0 ? count() * sizeHintForRow(0) : 0;
        return {QListWidget::sizeHint().width(), rows + 2 * frameWidth()};
    }
};

QLabel* value_label(const TraceValue& value, MatrixLayout layout) {
    const bool matrix = std::holds_alternative<glm::dmat4>(value);
    const int digits = matrix ? kReadableDigits : kValueDigits;
    auto* label = new QLabel(QString::fromStdString(value_text(value, layout, digits)));
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    if (!matrix) return label;
    label->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));  // the padded columns line up
    const QString full = QString::fromStdString(value_text(value, layout, kFullDigits));
    label->setToolTip("<pre>" + full.toHtmlEscaped() + "</pre>");
    return label;
}

}  // namespace

StepPlayer::StepPlayer(QWidget* parent)
    : QWidget(parent),
      list_(new StepList(this)),
      play_(new QPushButton("Play", this)),
      timer_(new QTimer(this)),
      layout_(new QComboBox(this)),
      explanation_(new QLabel),
      layout_note_(new QLabel),
      values_(new QGridLayout) {
    list_->setObjectName("steps");
    list_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // long titles are elided, whole in the tooltip
    list_->setTextElideMode(Qt::ElideRight);
    list_->setUniformItemSizes(true);
    list_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
    layout_->setObjectName("matrixLayout");
    layout_->addItem("as computed (column vectors)", static_cast<int>(MatrixLayout::column_vectors));
    layout_->addItem("as the papers print them (row vectors)", static_cast<int>(MatrixLayout::row_vectors));
    layout_->setToolTip(
        "ShadowLab computes with column vectors (GLM, p' = M p); the papers use Direct3D's row "
        "vectors (p' = p M) and print the transpose");
    auto* previous = new QPushButton("◀", this);
    auto* next = new QPushButton("▶", this);
    auto* copy = new QPushButton("Copy values", this);
    previous->setToolTip("previous step");
    next->setToolTip("next step");
    copy->setObjectName("copyValues");
    copy->setToolTip("the chosen step's values at full precision (17 significant digits)");
    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {previous, play_, next, copy}) buttons->addWidget(b);
    auto* matrices = new QFormLayout;
    matrices->addRow("Matrices", layout_);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(list_);
    layout->addLayout(buttons);
    layout->addLayout(matrices);
    layout->addWidget(details(), 1);

    connect(list_, &QListWidget::currentRowChanged, this, [this] {
        show_details();
        emit stepChosen(chosen());
    });
    connect(layout_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, &StepPlayer::show_details);
    connect(previous, &QPushButton::clicked, this, [this] { choose(std::max(0, list_->currentRow() - 1)); });
    connect(next, &QPushButton::clicked, this,
            [this] { choose(std::min(list_->count() - 1, list_->currentRow() + 1)); });
    connect(copy, &QPushButton::clicked, this, &StepPlayer::copy_values);
    connect(play_, &QPushButton::clicked, this, [this] {
        if (timer_->isActive()) return timer_->stop(), play_->setText("Play");
        if (list_->currentRow() == list_->count() - 1) choose(0);
        timer_->start(1200);
        play_->setText("Stop");
    });
    connect(timer_, &QTimer::timeout, this, [this] {
        if (list_->currentRow() >= list_->count() - 1) return timer_->stop(), play_->setText("Play");
        choose(list_->currentRow() + 1);
    });
}

// The chosen step's explanation, the layout note and its values, in the one area that scrolls.
QWidget* StepPlayer::details() {
    explanation_->setWordWrap(true);
    explanation_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout_note_->setWordWrap(true);
    layout_note_->setObjectName("matrixLayoutNote");
    values_->setColumnStretch(1, 1);
    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    column->addWidget(explanation_);
    column->addWidget(layout_note_);
    column->addLayout(values_);
    column->addStretch(1);
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName("stepDetails");
    scroll->setWidgetResizable(true);
    scroll->setWidget(content);
    scroll->setMinimumHeight(kDetailsMinHeight);
    return scroll;
}

void StepPlayer::set_trace(const Trace& trace) {
    const QString before = chosen();
    trace_ = &trace;
    const QSignalBlocker block(list_);
    list_->clear();
    int row = static_cast<int>(trace.steps().size()) - 1;
    for (size_t i = 0; i < trace.steps().size(); ++i) {
        const Step& s = trace.steps()[i];
        auto* item = new QListWidgetItem(QString("%1. %2").arg(i + 1).arg(QString::fromStdString(s.title)), list_);
        item->setData(Qt::UserRole, QString::fromStdString(s.id));
        item->setToolTip(QString("%1 (%2, %3 space)")
                             .arg(QString::fromStdString(s.title), QString::fromStdString(s.id), to_string(s.space)));
        if (QString::fromStdString(s.id) == before) row = static_cast<int>(i);
    }
    list_->updateGeometry();  // another count of rows, another height
    list_->setCurrentRow(row);
    show_details();
}

QString StepPlayer::chosen() const {
    const QListWidgetItem* item = list_->currentItem();
    return item ? item->data(Qt::UserRole).toString() : QString();
}

void StepPlayer::choose(int row) { list_->setCurrentRow(row); }

MatrixLayout StepPlayer::matrix_layout() const { return static_cast<MatrixLayout>(layout_->currentData().toInt()); }

void StepPlayer::set_matrix_layout(MatrixLayout layout) {
    layout_->setCurrentIndex(layout_->findData(static_cast<int>(layout)));
}

void StepPlayer::show_details() {
    while (QLayoutItem* item = values_->takeAt(0)) delete item->widget(), delete item;
    const Step* step = trace_ ? trace_->find(chosen().toStdString()) : nullptr;
    if (!step) return explanation_->clear(), layout_note_->clear();
    QString geometry;  // the shapes by name; their labels are part of them
    for (const NamedGeometry& g : step->geometry)
        if (!std::holds_alternative<Label>(g.geometry))
            geometry += (geometry.isEmpty() ? "" : ", ") + QString::fromStdString(g.name);
    explanation_->setText("<b>" + QString::fromStdString(step->title).toHtmlEscaped() + "</b> — " +
                          QString::fromStdString(step->explanation).toHtmlEscaped() +
                          (geometry.isEmpty() ? "" : "<br><i>drawn: " + geometry.toHtmlEscaped() + "</i>"));
    const bool has_matrix = std::any_of(step->values.begin(), step->values.end(), [](const NamedValue& v) {
        return std::holds_alternative<glm::dmat4>(v.value);
    });
    layout_note_->setText(has_matrix ? QString("<i>%1</i>").arg(layout_note(matrix_layout())) : QString());
    layout_note_->setVisible(has_matrix);
    // Names beside numbers and vectors; a matrix on the rows below its name, as wide as the area.
    int row = 0;
    for (const NamedValue& v : step->values) {
        QLabel* value = value_label(v.value, matrix_layout());
        value->setObjectName(QString::fromStdString(v.name));
        values_->addWidget(new QLabel(QString::fromStdString(v.name)), row, 0, Qt::AlignTop);
        if (std::holds_alternative<glm::dmat4>(v.value))
            values_->addWidget(value, ++row, 0, 1, 2);
        else
            values_->addWidget(value, row, 1);
        ++row;
    }
}

void StepPlayer::copy_values() const {
    const Step* step = trace_ ? trace_->find(chosen().toStdString()) : nullptr;
    if (!step) return;
    QString text;
    for (const NamedValue& v : step->values)
        text += QString::fromStdString(v.name + ":\n" + value_text(v.value, matrix_layout(), kFullDigits) + "\n");
    QApplication::clipboard()->setText(text);
}

}  // namespace shadowlab
