#include "scene/gltf_materials.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>

#include "scene/file_bytes.hpp"
#include "scene/png_alpha.hpp"

namespace shadowlab {
namespace {

using nlohmann::json;

constexpr double kDefaultCutoff = 0.5;  // glTF's alphaCutoff, and BLEND's as read here

// The images the materials name, each decoded once.
class ImageReader {
public:
    ImageReader(const GltfFields& fields, const json& root, const std::string& file)
        : fields_(fields), root_(root), folder_(std::filesystem::path(file).parent_path()) {}

    // The alpha of the image that the texture `index` names (at `path`) samples.
    std::shared_ptr<const AlphaTexture> texture(const json& index_value, const std::string& path) {
        return decoded(alpha_, index_value, path,
                       [](const std::string& bytes, const std::string& name) { return decode_png_alpha(bytes, name); });
    }

    // The colour of that image.
    std::shared_ptr<const ColourTexture> colour_texture(const json& index_value, const std::string& path) {
        return decoded(colour_, index_value, path, decode_colour_texture);
    }

    // The file the texture `index` names by its image's uri, where no such file is beside the model
    // (its textures left behind); nullopt where it is there or the image lies in a buffer.
    std::optional<std::string> missing_file(const json& index_value, const std::string& path) const {
        const std::size_t source = source_of(index_value, path);
        const std::string image_path = indexed("images", source);
        const json& image = fields_.array(root_, "", "images")[source];
        if (!fields_.member(image, image_path, "uri")) return std::nullopt;
        const std::string uri = fields_.text(image, image_path, "uri");
        if (uri.starts_with("data:") || std::filesystem::exists(folder_ / uri)) return std::nullopt;
        return uri;
    }

private:
    // The image the texture `index` samples.
    std::size_t source_of(const json& index_value, const std::string& path) const {
        const json& textures = fields_.array(root_, "", "textures");
        const std::size_t index = fields_.index(index_value, path, textures.size());
        const std::string texture_path = indexed("textures", index);
        const json& images = fields_.array(root_, "", "images");
        const std::optional<std::size_t> source = fields_.index(textures[index], texture_path, "source", images.size());
        if (!source) fields_.fail(texture_path + ".source", "required for an alpha-tested material, but missing");
        return *source;
    }

    // The image the texture `index` samples, decoded once per kind of texture.
    template <class Texture, class Decode>
    std::shared_ptr<const Texture> decoded(std::map<std::size_t, std::shared_ptr<const Texture>>& made,
                                           const json& index_value, const std::string& path, Decode decode) {
        const std::size_t source = source_of(index_value, path);
        std::shared_ptr<const Texture>& texture = made[source];
        if (!texture) {
            const ImageBytes image = image_bytes(fields_.array(root_, "", "images")[source], indexed("images", source));
            try {
                texture = std::make_shared<const Texture>(decode(image.bytes, image.name));
            } catch (const std::invalid_argument& problem) {
                fields_.fail(image.field, image.name + ": " + problem.what());
            }
        }
        return texture;
    }

    // An image's bytes, the name messages give it and the field that names them.
    struct ImageBytes {
        std::string bytes, name, field;
    };
    ImageBytes image_bytes(const json& image, const std::string& path) const {
        if (fields_.member(image, path, "uri")) {
            const std::string uri = fields_.text(image, path, "uri");
            if (uri.starts_with("data:"))
                fields_.fail(path + ".uri", "a data: URI; ShadowLab reads images from files or buffer views");
            return {.bytes = bytes_of(folder_ / uri, path + ".uri"), .name = uri, .field = path + ".uri"};
        }
        const json& views = fields_.array(root_, "", "bufferViews");
        const std::optional<std::size_t> view = fields_.index(image, path, "bufferView", views.size());
        if (!view) fields_.fail(path, "neither a uri nor a bufferView");
        return {.bytes = view_bytes(views[*view], indexed("bufferViews", *view)),
                .name = path,
                .field = path + ".bufferView"};
    }

    // A buffer view's bytes: a range of its buffer's file.
    std::string view_bytes(const json& view, const std::string& path) const {
        const json& buffers = fields_.array(root_, "", "buffers");
        const std::optional<std::size_t> buffer = fields_.index(view, path, "buffer", buffers.size());
        if (!buffer) fields_.fail(path + ".buffer", "required, but missing");
        const std::string buffer_path = indexed("buffers", *buffer);
        if (!fields_.member(buffers[*buffer], buffer_path, "uri"))
            fields_.fail(buffer_path, "a .glb's own binary chunk; ShadowLab reads images from files or buffer files");
        const std::string uri = fields_.text(buffers[*buffer], buffer_path, "uri");
        if (uri.starts_with("data:")) fields_.fail(buffer_path + ".uri", "a data: URI; ShadowLab reads buffer files");
        const std::string bytes = bytes_of(folder_ / uri, buffer_path + ".uri");
        const double offset = fields_.number(view, path, "byteOffset").value_or(0.0);
        const double length = fields_.required_number(view, path, "byteLength");
        const bool inside = offset >= 0.0 && length >= 0.0 && offset + length <= double(bytes.size());
        if (!inside) fields_.fail(path, "bytes beyond its buffer's " + std::to_string(bytes.size()));
        return bytes.substr(std::size_t(offset), std::size_t(length));
    }

    std::string bytes_of(const std::filesystem::path& file, const std::string& path) const {
        try {
            return file_bytes(file.string());
        } catch (const SceneError&) {
            fields_.fail(path, "cannot open " + file.string());
        }
    }

    const GltfFields& fields_;
    const json& root_;
    std::filesystem::path folder_;
    std::map<std::size_t, std::shared_ptr<const AlphaTexture>> alpha_;
    std::map<std::size_t, std::shared_ptr<const ColourTexture>> colour_;
};

// The base colour texture's index, where the material has one.
const json* base_colour_texture_index(const GltfFields& fields, const json& material, const std::string& path) {
    const json* pbr = fields.member(material, path, "pbrMetallicRoughness");
    const std::string pbr_path = path + ".pbrMetallicRoughness";
    const json* texture = pbr ? fields.member(*pbr, pbr_path, "baseColorTexture") : nullptr;
    return texture ? fields.member(*texture, pbr_path + ".baseColorTexture", "index") : nullptr;
}

// The factor's alpha and the texture it multiplies, from pbrMetallicRoughness.
AlphaTest base_colour_alpha(const GltfFields& fields, const json& material, const std::string& path,
                            ImageReader& images) {
    AlphaTest test;
    const json* pbr = fields.member(material, path, "pbrMetallicRoughness");
    if (!pbr) return test;
    const std::string pbr_path = path + ".pbrMetallicRoughness";
    if (const std::vector<double> factor = fields.numbers(*pbr, pbr_path, "baseColorFactor", 4); !factor.empty()) {
        fields.expect(factor[3] >= 0.0 && factor[3] <= 1.0, pbr_path + ".baseColorFactor[3]", "an alpha in [0, 1]",
                      factor[3]);
        test.factor = factor[3];
    }
    const json* texture = fields.member(*pbr, pbr_path, "baseColorTexture");
    if (!texture) return test;
    const std::string texture_path = pbr_path + ".baseColorTexture";
    const double coordinates = fields.number(*texture, texture_path, "texCoord").value_or(0.0);
    fields.expect(coordinates == 0.0, texture_path + ".texCoord", "0 (ShadowLab reads TEXCOORD_0)", coordinates);
    const json* index = fields.member(*texture, texture_path, "index");
    if (!index) fields.fail(texture_path + ".index", "required, but missing");
    test.texture = images.texture(*index, texture_path + ".index");
    return test;
}

// The material as messages name it: `materials[1] "LeatherPartsMat"`.
std::string material_name(const GltfFields& fields, const json& material, const std::string& path) {
    return fields.member(material, path, "name") ? path + " \"" + fields.text(material, path, "name") + "\"" : path;
}

// The base colour: the factor's colour (white without one, glTF's default) and the texture it multiplies,
// from pbrMetallicRoughness. A texture ShadowLab cannot read (missing, not a PNG, on other texture
// coordinates) is a note, the factor then shown alone.
BaseColour base_colour(const GltfFields& fields, const json& material, const std::string& path, ImageReader& images,
                       std::vector<Note>& notes) {
    BaseColour colour;
    const json* pbr = fields.member(material, path, "pbrMetallicRoughness");
    if (!pbr) return colour;
    const std::string pbr_path = path + ".pbrMetallicRoughness";
    if (const std::vector<double> factor = fields.numbers(*pbr, pbr_path, "baseColorFactor", 4); !factor.empty())
        colour.factor = {factor[0], factor[1], factor[2]};
    const json* texture = fields.member(*pbr, pbr_path, "baseColorTexture");
    if (!texture) return colour;
    const std::string texture_path = pbr_path + ".baseColorTexture";
    const auto factor_alone = [&](const std::string& why) {
        notes.push_back({NoteKind::base_colour_texture_missing,
                         material_name(fields, material, path) + ": " + why + ", its base colour factor shown"});
        return colour;
    };
    try {
        const double coordinates = fields.number(*texture, texture_path, "texCoord").value_or(0.0);
        if (coordinates != 0.0)
            return factor_alone(texture_path + ".texCoord is " + shown(coordinates) + " (ShadowLab reads TEXCOORD_0)");
        const json* index = fields.member(*texture, texture_path, "index");
        if (!index) fields.fail(texture_path + ".index", "required, but missing");
        if (const std::optional<std::string> missing = images.missing_file(*index, texture_path + ".index"))
            return factor_alone(*missing + " not found");
        colour.texture = images.colour_texture(*index, texture_path + ".index");
    } catch (const SceneError& unread) {
        return factor_alone(unread.json_path() + ": " + unread.problem());
    }
    return colour;
}

}  // namespace

GltfMaterials read_gltf_materials(const GltfFields& fields, const json& root, const std::string& file) {
    GltfMaterials out;
    ImageReader images(fields, root, file);
    const json& materials = fields.array(root, "", "materials");
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const std::string path = indexed("materials", i);
        out.colours.push_back(
            std::make_shared<const BaseColour>(base_colour(fields, materials[i], path, images, out.notes)));
        const std::string mode =
            fields.member(materials[i], path, "alphaMode") ? fields.text(materials[i], path, "alphaMode") : "OPAQUE";
        if (mode == "OPAQUE") {
            out.tests.push_back(nullptr);
            continue;
        }
        if (mode != "MASK" && mode != "BLEND")
            fields.fail(path + ".alphaMode", "expected \"OPAQUE\", \"MASK\" or \"BLEND\", got \"" + mode + "\"");
        const std::string name = material_name(fields, materials[i], path);
        const json* texture = base_colour_texture_index(fields, materials[i], path);
        if (const std::optional<std::string> missing =
                texture ? images.missing_file(*texture, path + ".pbrMetallicRoughness.baseColorTexture.index")
                        : std::nullopt) {
            out.notes.push_back({NoteKind::alpha_texture_missing, name + ": " + *missing + " not found, opaque"});
            out.tests.push_back(nullptr);
            continue;
        }
        AlphaTest test = base_colour_alpha(fields, materials[i], path, images);
        test.cutoff =
            mode == "MASK" ? fields.number(materials[i], path, "alphaCutoff").value_or(kDefaultCutoff) : kDefaultCutoff;
        fields.expect(test.cutoff >= 0.0, path + ".alphaCutoff", "a cutoff of 0 or more", test.cutoff);
        if (mode == "BLEND") out.notes.push_back({NoteKind::blend_read_as_mask, name + " casts as MASK at cutoff 0.5"});
        out.tests.push_back(std::make_shared<const AlphaTest>(std::move(test)));
    }
    return out;
}

}  // namespace shadowlab
