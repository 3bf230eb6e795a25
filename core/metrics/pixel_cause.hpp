#pragma once
// Why a pixel's shadow is wrong: every misclassified receiver pixel gets exactly one cause, decided
// from what its lookup actually read (metrics/pixel_evidence.hpp), not guessed from the picture.
// Every cause is one CauseInfo in the table of pixel_cause.cpp: its name, its meaning, the test that
// gives it and the remedy it implies (metrics/diagnosis.hpp measures that remedy). The first cause
// in the table whose test holds is the pixel's: the table's order is the precedence.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "methods/settings.hpp"

namespace shadowlab {

struct Method;
struct PixelEvidence;

enum class PixelCause : uint8_t {
    none,  // not misclassified, or not judged
    technique,
    contact,
    outside_map,
    filter,
    seam,
    depth_precision,
    acne,
    peter_panning,
    projection,
    under_sampling,
    undecided,
};

// What a remedy starts from: the run whose pixels were diagnosed.
struct RemedyInputs {
    const Method& method;
    const Settings& settings;  // resolved: every setting of the method present
    int resolution = 0;
    double bias = -1.0;              // the CLI's constant --bias, or negative
    double m_perspective_p95 = 0.0;  // the run's perspective factor of m and m itself (95th percentiles)
    double m_p95 = 0.0;
};

// The change a cause implies, to be measured: the method, its settings, resolution and bias.
struct Remedy {
    std::string change;  // as users read it: "bias_slope 1 → 2"
    const Method* method = nullptr;
    Settings settings;
    int resolution = 0;
    double bias = -1.0;
};

struct CauseInfo {
    PixelCause kind;
    const char* name;                                         // as in measure --json: "acne"
    const char* meaning;                                      // one line: what the lookup read that makes it this cause
    std::array<unsigned char, 3> colour;                      // the Error view's overlay and legend
    bool (*holds)(const PixelEvidence& e);                    // the test; the first that holds decides
    std::optional<Remedy> (*remedy)(const RemedyInputs& in);  // null or nullopt: none to measure
};

// Every cause but `none`, in precedence order.
const std::vector<CauseInfo>& all_causes();
const CauseInfo& info(PixelCause kind);
const char* to_string(PixelCause kind);  // info(kind).name; "none" for none
// The first cause whose test holds (undecided holds always).
PixelCause cause_of(const PixelEvidence& evidence);

}  // namespace shadowlab
