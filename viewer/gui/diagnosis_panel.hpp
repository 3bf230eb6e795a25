#pragma once
// The Diagnosis dock, "why is my shadow wrong?" for the inspection shown: the causes of its
// misclassified pixels (metrics/pixel_cause.hpp) ranked by their pixels (count_causes), each with
// its share of the receiver pixels, its colour in the Error view's causes mode and its meaning on
// hover. A cause whose remedy the run can take has a button beneath it naming the change
// ("bias_slope 0 → 1") that asks the window for the run with it: the remedy's method, settings,
// resolution and bias.
#include <QString>
#include <QWidget>

#include "metrics/diagnosis.hpp"
#include "model/inspection.hpp"

class QLabel;
class QTableWidget;

namespace shadowlab {

class DiagnosisPanel : public QWidget {
    Q_OBJECT
public:
    explicit DiagnosisPanel(QWidget* parent = nullptr);

    // The causes of `error`, the inspection's error against the reference of one image size, and
    // each cause's remedy for that run.
    void show_diagnosis(const Inspection& inspection, const ShadowError& error);
    const Diagnosis& diagnosis() const { return diagnosis_; }
    QSize sizeHint() const override { return {300, 340}; }  // a few causes and their buttons, under the steps

signals:
    // The run a remedy asks for, and the change as users read it.
    void remedyChosen(const InspectionRequest& request, const QString& change);

private:
    void add_rows(const CauseCount& cause, const std::optional<Remedy>& remedy);

    QLabel* summary_;
    QTableWidget* table_;
    Diagnosis diagnosis_;
};

// The request of the run a remedy describes: its method, every setting as text, its resolution and bias.
InspectionRequest request_for(const Remedy& remedy);

}  // namespace shadowlab
