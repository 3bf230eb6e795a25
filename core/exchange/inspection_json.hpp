#pragma once
// The JSON form of a method's result, as `shadowlab inspect --json` prints it:
// {"method", "settings", "fallback", "fallbacks", "inputs": {"receivers", "casters"}, "maps",
// "selection", "steps"}.
// Matrices are four rows of the column-vector matrix.
#include <string>
#include <nlohmann/json.hpp>

#include "registry/method.hpp"

namespace shadowlab {

using Json = nlohmann::ordered_json;

Json to_json(const glm::dmat4& m);
Json to_json(const TraceValue& value);
Json to_json(const NamedGeometry& geometry);
Json to_json(const Step& step);
Json to_json(const ShadowMap& map);
Json to_json(const MapSelection& selection);
// A virtual map's page table in brief (what measure --json reports as "pages"), and whole.
Json pages_json(const PageTable& table);
Json to_json(const PageTable& table);
// [{"kind": "empty intersection body", "message": ...}, ...]
Json to_json(const std::vector<Note>& notes);

Json inspection_json(const std::string& method, const Settings& settings, const ShadowInputs& inputs,
                     const ShadowSetup& setup, const Trace& trace);

// A geometric technique's inspection: {"method", "settings", "limits", "cost": {"polygons",
// "fill_mean", "fill_max"}, "steps"} (no maps, no input boxes).
Json technique_inspection_json(const std::string& technique, const Settings& settings, const GeometryResult& result,
                               const Trace& trace);

}  // namespace shadowlab
