#pragma once
// The alpha tests of a glTF file's materials (glTF 2.0, "Alpha Coverage"): alphaMode MASK with its
// alphaCutoff (0.5 by default), the alpha of pbrMetallicRoughness.baseColorFactor times that of its
// baseColorTexture (a PNG image: a file by `uri`, or a `bufferView` of a buffer file). A shadow map keeps
// one depth per texel and no partial coverage, so a BLEND material casts as MASK at 0.5, said by a
// note (blend_read_as_mask); OPAQUE (the default) has no test.
#include <memory>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "notes/note.hpp"
#include "scene/alpha_test.hpp"
#include "scene/gltf_fields.hpp"

namespace shadowlab {

struct MaterialAlpha {
    std::vector<std::shared_ptr<const AlphaTest>> tests;  // per material of the file; null: opaque
    std::vector<Note> notes;                              // the BLEND materials read as MASK
};

// Refuses with the file and the field's JSON path (materials[0].alphaCutoff, images[1].uri) what it
// cannot read: a bad field, an image that is missing or not a PNG ("images[0].uri: fence.png: not a PNG
// image"), a data: URI, a .glb's own binary chunk.
MaterialAlpha read_material_alpha(const GltfFields& fields, const nlohmann::json& root, const std::string& file);

}  // namespace shadowlab
