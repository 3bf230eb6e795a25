#pragma once
// The JSON form of a method's result, as `shadowlab inspect --json` prints it:
// {"method", "settings", "fallback", "inputs": {"receivers", "casters"}, "maps", "steps"}.
// Matrices are four rows of the column-vector matrix.
#include <string>
#include <nlohmann/json.hpp>

#include "methods/method.hpp"
#include "techniques/technique.hpp"

namespace shadowlab {

using Json = nlohmann::ordered_json;

Json to_json(const glm::dmat4& m);
Json to_json(const TraceValue& value);
Json to_json(const NamedGeometry& geometry);
Json to_json(const Step& step);
Json to_json(const ShadowMap& map);

Json inspection_json(const std::string& method, const Settings& settings, const ShadowInputs& inputs,
                     const ShadowSetup& setup, const Trace& trace);

// A geometric technique's inspection: {"method", "settings", "fallback", "cost": {"polygons",
// "fill_mean", "fill_max"}, "steps"} (no maps, no input boxes).
Json technique_inspection_json(const std::string& technique, const Settings& settings, const TechniqueResult& result,
                               const Trace& trace);

}  // namespace shadowlab
