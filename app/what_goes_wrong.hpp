#pragma once
// A lesson's last section, "What goes wrong": the run measured against the exact reference of the
// pictures' camera image, its misclassified pixels ranked by cause (metrics/pixel_cause.hpp) with
// each cause's meaning and its remedy measured (metrics/diagnosis.hpp: what share of the cause it
// removes, what it adds elsewhere), and the Error view coloured by cause over the same pixels.
#include "lesson_page.hpp"

namespace shadowlab {

std::string what_goes_wrong(const Inspection& in, const LessonOptions& options, const PictureSource& source);

}  // namespace shadowlab
