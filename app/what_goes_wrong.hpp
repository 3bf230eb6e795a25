#pragma once
// A lesson's last section, "What goes wrong": the run measured against the exact reference of the
// pictures' camera image, its misclassified pixels ranked by cause (metrics/pixel_cause.hpp) with
// each cause's meaning and its remedy measured (metrics/diagnosis.hpp: what share of the cause it
// removes, what it adds elsewhere), and the Error view coloured by cause over the same pixels.
#include "lesson_page.hpp"
#include "metrics/diagnosis.hpp"

namespace shadowlab {

// The lesson's section: the run measured and diagnosed on the pictures' camera image.
std::string what_goes_wrong(const Inspection& in, const LessonOptions& options, const PictureSource& source);

// The section of a run already measured on `context` and diagnosed (`shadowlab compare` writes one per
// configuration): its HTML id and title, and its Error-by-cause picture's file name and size.
struct WrongSection {
    std::string id = "what-goes-wrong", heading = "What goes wrong", picture = "what-goes-wrong-error-causes.png";
    int width = 640, height = 400;
};
std::string what_goes_wrong_section(const Inspection& in, const MeasureContext& context, const Measurement& run,
                                    const Diagnosis& diagnosis, const WrongSection& section,
                                    const PictureSource& source);

}  // namespace shadowlab
