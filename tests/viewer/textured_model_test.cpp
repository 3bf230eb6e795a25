// Models in their own colours (scene/base_colour.hpp): a quad textured with a four-colour checker, as a
// glTF file and as an OBJ with its MTL, written by the test, drawn in the Camera view under a light
// 60° off its normal. Each quadrant shows its texel's colour, scaled by one shading factor for all
// channels and quadrants (the texture read as sRGB, decoded, and shown encoded again); a base colour
// factor multiplies in linear, as glTF says; a texture that is not there is a named note, the model
// loading with its factor alone.
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <gtest/gtest.h>

#include "model/inspection.hpp"
#include "notes/note.hpp"
#include "render/rgb_image.hpp"
#include "scene/base_colour.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"
#include "views/offscreen_view.hpp"
#include "views/view.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 480, kHeight = 360;
constexpr int kTexels = 64;  // the checker's side: four quadrants of 32 x 32 texels

using Colour = std::array<int, 3>;
// The image's quadrants as it is seen (its top row first), chosen so that a missing or doubled sRGB
// decoding changes their channels' ratios.
constexpr Colour kTopLeft{230, 60, 30}, kTopRight{40, 200, 90}, kBottomLeft{50, 80, 220}, kBottomRight{240, 210, 40};

// A folder of its own for one test's files, removed afterwards.
class ModelFolder {
public:
    explicit ModelFolder(const std::string& name)
        : path_(std::filesystem::temp_directory_path() / ("shadowlab_textured_" + name)) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ModelFolder() { std::filesystem::remove_all(path_); }
    ModelFolder(const ModelFolder&) = delete;
    ModelFolder& operator=(const ModelFolder&) = delete;

    std::string file(const std::string& name) const { return (path_ / name).string(); }
    void write(const std::string& name, const std::string& bytes) const {
        std::ofstream(file(name), std::ios::binary) << bytes;
    }
    void write_checker(const std::string& name) const {
        RgbImage image(kTexels, kTexels);
        for (int y = 0; y < kTexels; ++y)  // row 0 the top, as the PNG stores it
            for (int x = 0; x < kTexels; ++x) {
                const bool top = y < kTexels / 2, left = x < kTexels / 2;
                const Colour& c = top ? (left ? kTopLeft : kTopRight) : (left ? kBottomLeft : kBottomRight);
                std::copy(c.begin(), c.end(), image.at(x, y));
            }
        write_png(image, file(name));
    }

private:
    std::filesystem::path path_;
};

template <class T>
void append(std::string& bytes, const std::vector<T>& values) {
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// A quad in the plane z = 0 ((-1, -1) to (1, 1), facing +z), the camera on +z looking at it and a sun
// travelling 60° off its normal (KHR_lights_punctual), its one material's base colour `factor` and,
// when `texture` is not empty, that image as its texture; glTF's texture coordinates put the image's
// top-left corner at the quad's top-left.
void write_gltf_quad(const ModelFolder& folder, const std::string& texture, const std::string& factor) {
    std::string bin;
    append(bin, std::vector<float>{-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});  // positions
    append(bin, std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0});                  // TEXCOORD_0, v down
    append(bin, std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
    folder.write("quad.bin", bin);
    const std::string textured = texture.empty() ? "" : R"(, "baseColorTexture": {"index": 0})";
    const std::string images =
        texture.empty() ? "" : R"(, "textures": [{"source": 0}], "images": [{"uri": ")" + texture + R"("}])";
    folder.write("quad.gltf", R"({"asset": {"version": "2.0"}, "scene": 0,
  "scenes": [{"nodes": [0, 1, 2]}],
  "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]},
            {"extensions": {"KHR_lights_punctual": {"light": 0}}, "rotation": [0, 0.5, 0, 0.8660254]}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.9, "aspectRatio": 1.3333333, "znear": 0.5, "zfar": 10}}],
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional"}]}},
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
  "materials": [{"name": "checker", "pbrMetallicRoughness": {"baseColorFactor": )" +
                                  factor + textured + R"(}}],
  "buffers": [{"uri": "quad.bin", "byteLength": )" +
                                  std::to_string(bin.size()) + R"(}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]
  )" + images + "}\n");
}

// The same quad as an OBJ (texture coordinates v up, as OBJ has them) with its MTL (Kd and map_Kd),
// placed by a scene JSON with the same camera and light.
void write_obj_quad(const ModelFolder& folder, const std::string& texture, const std::string& kd) {
    folder.write("quad.mtl", "newmtl checker\nKd " + kd + (texture.empty() ? "" : "\nmap_Kd " + texture) + "\n");
    folder.write("quad.obj",
                 "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                 "usemtl checker\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    folder.write("quad.json", R"({"name": "quad",
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 51.566, "aspect": 1.3333333,
             "near": 0.5, "far": 10},
  "light": {"type": "directional", "direction": [-0.8660254, 0, -0.5]},
  "objects": [{"type": "mesh", "name": "quad", "file": "quad.obj"}]})");
}

// The Camera view under a map method (ShadowMapPass) or a technique (StencilVolumePass).
RgbImage camera_view_of(const Scene& scene, const std::string& method = "focused") {
    InspectionRequest request;
    request.method = method;
    request.resolution = 1024;
    request.image_width = kWidth;
    request.image_height = kHeight;
    const Inspection inspection = inspect_scene(scene, request);
    return render_view(inspection, *find_view("camera"), ViewOptions{}, kWidth, kHeight);
}

// The mean colour of the pixels around a world point's pixel.
glm::dvec3 colour_at(const RgbImage& image, const Camera& camera, const glm::dvec3& point) {
    const glm::ivec2 centre = pixel_of(camera, point, image.width, image.height);
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int y = centre.y - 4; y <= centre.y + 4; ++y)
        for (int x = centre.x - 4; x <= centre.x + 4; ++x, ++count) {
            const unsigned char* c = image.at(x, y);
            sum += glm::dvec3(c[0], c[1], c[2]);
        }
    return sum / double(count);
}

glm::dvec3 as_vector(const Colour& c) { return {double(c[0]), double(c[1]), double(c[2])}; }

// Each quadrant's centre shows its texel's colour times one shading factor, the same for every channel
// and quadrant: the least-squares factor over all twelve channels, each within 4 levels of it.
void expect_checker(const Scene& scene, const std::string& method) {
    const RgbImage image = camera_view_of(scene, method);
    const std::vector<std::pair<glm::dvec3, Colour>> quadrants{{{-0.5, 0.5, 0.0}, kTopLeft},
                                                               {{0.5, 0.5, 0.0}, kTopRight},
                                                               {{-0.5, -0.5, 0.0}, kBottomLeft},
                                                               {{0.5, -0.5, 0.0}, kBottomRight}};
    double seen_times_texel = 0.0, texel_squared = 0.0;
    for (const auto& [point, texel] : quadrants) {
        seen_times_texel += glm::dot(colour_at(image, scene.camera, point), as_vector(texel));
        texel_squared += glm::dot(as_vector(texel), as_vector(texel));
    }
    const double shading = seen_times_texel / texel_squared;
    EXPECT_GT(shading, 0.4);  // lit: ambient 0.35 plus diffuse at cos 60°, not tinted as shadowed
    EXPECT_LT(shading, 1.0);  // below white, so that no channel clips
    double farthest = 0.0;
    for (const auto& [point, texel] : quadrants) {
        const glm::dvec3 seen = colour_at(image, scene.camera, point);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(seen[c], shading * texel[c], 4.0)
                << "quadrant at (" << point.x << ", " << point.y << "), channel " << c;
            farthest = std::max(farthest, std::abs(seen[c] - shading * texel[c]));
        }
    }
    std::cout << std::filesystem::path(scene.source_file).filename().string() << " under " << method
              << ": each quadrant its texel's colour times " << shading << ", within " << farthest << " levels\n";
}

// The colour an untextured material of linear `factor` shows in the quad's middle, as ratios to its red.
glm::dvec2 green_and_blue_over_red(const Scene& scene) {
    const glm::dvec3 seen = colour_at(camera_view_of(scene), scene.camera, glm::dvec3(0.0));
    return {seen.g / seen.r, seen.b / seen.r};
}

bool has_note(const Scene& scene, NoteKind kind, const std::string& naming) {
    for (const Note& note : scene.notes)
        if (note.kind == kind && note.message.find(naming) != std::string::npos) return true;
    return false;
}

// The quad as a glTF file or as an OBJ with its MTL, loaded, with its texture as `texture` says: the
// checker, none, a file named but left behind, or a file that is not a PNG.
enum class Format { gltf, obj };
enum class Texture { checker, none, left_behind, not_a_png };

Scene loaded_quad(Format format, Texture texture, const glm::dvec3& factor) {
    const ModelFolder folder(std::string(format == Format::gltf ? "gltf" : "obj") + "_" +
                             std::to_string(static_cast<int>(texture)));
    const std::string file = texture == Texture::checker       ? "checker.png"
                             : texture == Texture::left_behind ? "left_behind.png"
                             : texture == Texture::not_a_png   ? "not_a_png.png"
                                                               : "";
    if (texture == Texture::checker) folder.write_checker(file);
    if (texture == Texture::not_a_png) folder.write(file, "GIF89a");
    const std::string r = std::to_string(factor.r), g = std::to_string(factor.g), b = std::to_string(factor.b);
    if (format == Format::gltf) {
        write_gltf_quad(folder, file, "[" + r + ", " + g + ", " + b + ", 1]");
        return load_scene(folder.file("quad.gltf"));
    }
    write_obj_quad(folder, file, r + " " + g + " " + b);
    return load_scene(folder.file("quad.json"));
}

}  // namespace

TEST(TexturedModel, QuadShowsItsTexturesColoursInEachQuadrantFromGltfAndObjUnderBothPasses) {
    for (const Format format : {Format::gltf, Format::obj}) {
        const Scene scene = loaded_quad(format, Texture::checker, glm::dvec3(1.0));
        EXPECT_TRUE(scene.notes.empty()) << describe(scene.notes);
        for (const std::string method : {"focused", "volumes"}) expect_checker(scene, method);
    }
}

// glTF 2.0, 3.9.2: the factor is linear; shown, it is sRGB-encoded: (1, 0.5, 0.2) as (1, 0.735, 0.485)
// of its red, not (1, 0.5, 0.2). Shading scales the three channels alike, so the ratios hold.
TEST(TexturedModel, BaseColourFactorIsShownSrgbEncodedFromGltfAndObj) {
    const glm::dvec2 expected(srgb_from_linear(0.5), srgb_from_linear(0.2));
    ASSERT_NEAR(expected.x, 0.7354, 1e-3);
    ASSERT_NEAR(expected.y, 0.4845, 1e-3);
    for (const Format format : {Format::gltf, Format::obj}) {
        const glm::dvec2 seen = green_and_blue_over_red(loaded_quad(format, Texture::none, {1.0, 0.5, 0.2}));
        EXPECT_NEAR(seen.x, expected.x, 0.02);
        EXPECT_NEAR(seen.y, expected.y, 0.02);
    }
}

// A texture left behind or unreadable: the model loads, the note names the texture (and a glTF
// material), and the quad shows its factor alone (here a linear 0.5 grey: every channel alike).
TEST(TexturedModel, MissingOrUnreadableTextureIsANamedNoteAndTheFactorShows) {
    const Scene left_behind = loaded_quad(Format::gltf, Texture::left_behind, glm::dvec3(0.5));
    EXPECT_TRUE(has_note(left_behind, NoteKind::base_colour_texture_missing, "\"checker\": left_behind.png not found"))
        << describe(left_behind.notes);
    const glm::dvec2 grey = green_and_blue_over_red(left_behind);
    EXPECT_NEAR(grey.x, 1.0, 0.02);
    EXPECT_NEAR(grey.y, 1.0, 0.02);
    const Scene unreadable = loaded_quad(Format::obj, Texture::not_a_png, glm::dvec3(0.5));
    EXPECT_TRUE(
        has_note(unreadable, NoteKind::base_colour_texture_missing, "quad.obj: map_Kd not_a_png.png: not a PNG image"))
        << describe(unreadable.notes);
}
