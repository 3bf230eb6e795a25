#pragma once
// What ShadowLab reads of a glTF file's materials: each one's base colour (scene/base_colour.hpp:
// pbrMetallicRoughness.baseColorFactor and its baseColorTexture, for the Camera view), and its alpha test
// (glTF 2.0, "Alpha Coverage"): alphaMode MASK with its
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
#include "scene/base_colour.hpp"
#include "scene/gltf_fields.hpp"

namespace shadowlab {

struct GltfMaterials {
    std::vector<std::shared_ptr<const AlphaTest>> tests;     // per material of the file; null: opaque
    std::vector<std::shared_ptr<const BaseColour>> colours;  // per material of the file
    std::vector<Note> notes;  // the BLEND materials read as MASK, the textures missing or unread
};

// A base colour texture that is missing or unreadable is a note (base_colour_texture_missing), the
// material keeping its factor alone. Refuses with the file and the field's JSON path (materials[0].alphaCutoff,
// images[1].uri) what it cannot read: a bad field, an image that is missing or not a PNG ("images[0].uri: fence.png:
// not a PNG image"), a data: URI, a .glb's own binary chunk.
GltfMaterials read_gltf_materials(const GltfFields& fields, const nlohmann::json& root, const std::string& file);

}  // namespace shadowlab
