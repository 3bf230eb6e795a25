#pragma once
// The step player: the method's steps in a list; the chosen one's explanation and values (matrices
// in a table that can be copied); previous, next and play.
#include <QWidget>

#include "trace/trace.hpp"

class QLabel;
class QListWidget;
class QPushButton;
class QTableWidget;
class QTimer;

namespace shadowlab {

class StepPlayer : public QWidget {
    Q_OBJECT
public:
    explicit StepPlayer(QWidget* parent = nullptr);

    // Keeps the chosen step when the new trace has a step of that id, else chooses the last.
    void set_trace(const Trace& trace);
    QString chosen() const;  // the step id
    void choose(int row);

signals:
    void stepChosen(const QString& id);

private:
    void show_details();
    void copy_values() const;

    const Trace* trace_ = nullptr;
    QListWidget* list_;
    QLabel* explanation_;
    QTableWidget* values_;
    QPushButton* play_;
    QTimer* timer_;
};

}  // namespace shadowlab
