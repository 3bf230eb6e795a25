#pragma once
// The step player: the method's steps in a list as tall as its rows (the details below scroll
// instead, down to a minimum height); previous, next and play; the chosen step's explanation and
// values, matrices as aligned grids laid out as computed (column vectors) or as the papers print
// them (row vectors), with full precision in their tooltips and in "Copy values".
#include <QWidget>

#include "io/value_text.hpp"
#include "trace/trace.hpp"

class QComboBox;
class QGridLayout;
class QLabel;
class QListWidget;
class QPushButton;
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
    MatrixLayout matrix_layout() const;
    void set_matrix_layout(MatrixLayout layout);

signals:
    void stepChosen(const QString& id);

private:
    QWidget* details();
    void show_details();
    void copy_values() const;

    const Trace* trace_ = nullptr;
    QListWidget* list_;
    QPushButton* play_;
    QTimer* timer_;
    QComboBox* layout_;
    QLabel* explanation_;
    QLabel* layout_note_;
    QGridLayout* values_;
};

}  // namespace shadowlab
