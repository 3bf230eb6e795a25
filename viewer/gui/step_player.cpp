#include "gui/step_player.hpp"

#include <QApplication>
#include <QClipboard>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include "io/value_text.hpp"

namespace shadowlab {

StepPlayer::StepPlayer(QWidget* parent)
    : QWidget(parent),
      list_(new QListWidget(this)),
      explanation_(new QLabel(this)),
      values_(new QTableWidget(0, 2, this)),
      play_(new QPushButton("Play", this)),
      timer_(new QTimer(this)) {
    list_->setObjectName("steps");
    explanation_->setWordWrap(true);
    explanation_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    values_->setHorizontalHeaderLabels({"Value", ""});
    values_->horizontalHeader()->setStretchLastSection(true);
    values_->verticalHeader()->hide();
    values_->setFont(QFont("monospace"));
    auto* previous = new QPushButton("◀ Previous", this);
    auto* next = new QPushButton("Next ▶", this);
    auto* copy = new QPushButton("Copy values", this);
    auto* buttons = new QHBoxLayout;
    for (QPushButton* b : {previous, play_, next, copy}) buttons->addWidget(b);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(list_, 2);
    layout->addLayout(buttons);
    layout->addWidget(explanation_);
    layout->addWidget(values_, 3);

    connect(list_, &QListWidget::currentRowChanged, this, [this] {
        show_details();
        emit stepChosen(chosen());
    });
    connect(previous, &QPushButton::clicked, this, [this] { choose(std::max(0, list_->currentRow() - 1)); });
    connect(next, &QPushButton::clicked, this, [this] { choose(std::min(list_->count() - 1, list_->currentRow() + 1)); });
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

void StepPlayer::set_trace(const Trace& trace) {
    const QString before = chosen();
    trace_ = &trace;
    const QSignalBlocker block(list_);
    list_->clear();
    int row = static_cast<int>(trace.steps().size()) - 1;
    for (size_t i = 0; i < trace.steps().size(); ++i) {
        const Step& s = trace.steps()[i];
        list_->addItem(QString("%1. %2  [%3, %4]").arg(i + 1).arg(QString::fromStdString(s.title),
                                                                  QString::fromStdString(s.id), to_string(s.space)));
        list_->item(static_cast<int>(i))->setData(Qt::UserRole, QString::fromStdString(s.id));
        if (QString::fromStdString(s.id) == before) row = static_cast<int>(i);
    }
    list_->setCurrentRow(row);
    show_details();
}

QString StepPlayer::chosen() const {
    const QListWidgetItem* item = list_->currentItem();
    return item ? item->data(Qt::UserRole).toString() : QString();
}

void StepPlayer::choose(int row) { list_->setCurrentRow(row); }

void StepPlayer::show_details() {
    values_->setRowCount(0);
    const Step* step = trace_ ? trace_->find(chosen().toStdString()) : nullptr;
    if (!step) return explanation_->clear();
    QString geometry;
    for (const NamedGeometry& g : step->geometry) geometry += (geometry.isEmpty() ? "" : ", ") + QString::fromStdString(g.name);
    explanation_->setText("<b>" + QString::fromStdString(step->title) + "</b> — " +
                          QString::fromStdString(step->explanation).toHtmlEscaped() +
                          (geometry.isEmpty() ? "" : "<br><i>drawn: " + geometry + "</i>"));
    for (const NamedValue& v : step->values) {
        const int row = values_->rowCount();
        values_->insertRow(row);
        values_->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(v.name)));
        values_->setItem(row, 1, new QTableWidgetItem(QString::fromStdString(value_text(v.value))));
    }
    values_->resizeRowsToContents();
}

void StepPlayer::copy_values() const {
    QString text;
    for (int row = 0; row < values_->rowCount(); ++row)
        text += values_->item(row, 0)->text() + ":\n" + values_->item(row, 1)->text() + "\n";
    QApplication::clipboard()->setText(text);
}

}  // namespace shadowlab
