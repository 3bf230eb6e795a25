// The Texels view and the Shadow map view's atlas (under Xvfb): a texel carried back to the world lands
// on the scene's surfaces and maps back to itself; its footprint lies on the surface's plane; the
// drawn texels are capped by a stride the caption names; every map method draws texels and a
// technique says it has none; a texture of two tiles shows the border between them and a label each.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include "maps/map_lookup.hpp"
#include "registry/method.hpp"
#include "render/x_display.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"
#include "views/view_parts.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 640, kHeight = 360;

Scene box_on_plane() { return shipped_scene("box_on_plane", kWidth, kHeight); }

// The distance from p to the nearest scene triangle whose plane it projects into (inside the
// triangle, up to `slack` of its plane's units), and that triangle's index; -1 where none.
struct Nearest {
    double distance = 1e300;
    int triangle = -1;
};
Nearest nearest_triangle(const WorldTriangles& scene, const glm::dvec3& p, double slack) {
    Nearest nearest;
    for (size_t t = 0; t < scene.triangles.size(); ++t) {
        const glm::dvec3 a = scene.vertices[scene.triangles[t][0]], b = scene.vertices[scene.triangles[t][1]],
                         c = scene.vertices[scene.triangles[t][2]];
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        const double distance = std::abs(glm::dot(p - a, n));
        const glm::dvec3 q = p - glm::dot(p - a, n) * n;  // on the plane
        bool inside = true;                               // on the inner side of each edge, within the slack
        for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
            inside = inside && glm::dot(glm::cross(to - from, q - from), n) >= -slack * glm::length(to - from);
        if (inside && distance < nearest.distance) nearest = {distance, static_cast<int>(t)};
    }
    return nearest;
}

double distance_to_plane(const WorldTriangles& scene, int triangle, const glm::dvec3& p) {
    const glm::dvec3 a = scene.vertices[scene.triangles[triangle][0]], b = scene.vertices[scene.triangles[triangle][1]],
                     c = scene.vertices[scene.triangles[triangle][2]];
    return std::abs(glm::dot(p - a, glm::normalize(glm::cross(b - a, c - a))));
}

// The view built in a window of the given size (not rendered) and the texts it holds: captions,
// legends and labels.
std::vector<std::string> texts_of(const Inspection& in, const View& view, int width, int height) {
    const XDisplay x("texels test");
    vtkNew<vtkRenderWindow> window;
    window->SetInteractor(nullptr);
    window->SetDisplayId(x.handle());
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    build_view(renderer, in, view, {.width = width, .height = height});
    std::vector<std::string> texts;
    vtkPropCollection* props = renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp()) {
        if (auto* text = vtkTextActor::SafeDownCast(prop)) texts.push_back(text->GetInput());
        if (auto* label = vtkBillboardTextActor3D::SafeDownCast(prop)) texts.push_back(label->GetInput());
    }
    window->Finalize();
    return texts;
}

bool any_contains(const std::vector<std::string>& texts, const std::string& part) {
    return std::any_of(texts.begin(), texts.end(),
                       [&](const std::string& t) { return t.find(part) != std::string::npos; });
}

// The first map's two tones, drawn unlit: warm and saturated, brighter than any dimmed scene colour.
size_t first_map_pixels(const RgbImage& image) {
    size_t count = 0;
    for (int y = 0; y < image.height - 40; ++y)  // the caption's rows left out
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* c = image.at(x, y);
            count += c[0] >= 130 && c[1] >= 0.5 * c[0] && c[1] <= 0.7 * c[0] && c[2] <= 0.25 * c[0];
        }
    return count;
}

bool has_colour(const unsigned char* c, const glm::dvec3& colour) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(c[i] - 255.0 * colour[i]) > 6.0) return false;
    return true;
}

// Two tiles of a 2x2 atlas, lower left and upper right, chosen by view depth: the uniform map in each,
// split at the camera's target (as tests/viewer/extension_test.cpp builds them), rasterized again.
Inspection two_tile_atlas(const Scene& scene, int resolution) {
    Inspection in = inspect(scene, "uniform", resolution);
    const ShadowMap uniform = in.setup.maps.at(0);
    in.setup.maps.clear();
    for (const glm::dvec4& tile : {glm::dvec4(0.0, 0.0, 0.5, 0.5), glm::dvec4(0.5, 0.5, 1.0, 1.0)}) {
        ShadowMap map = uniform;
        map.viewport = tile;
        in.setup.maps.push_back(map);
    }
    const Camera& camera = scene.camera;
    in.setup.selection = {.rule = MapSelection::Rule::view_depth,
                          .eye = camera.position,
                          .view_axis = camera.view_direction(),
                          .split_depths = {0.0, glm::length(camera.target - camera.position), camera.far}};
    return in;  // its depth map is rasterized from this setup when first read
}

}  // namespace

// Each texel carried back lands on a surface of the scene (its centre on a triangle, to float32 depth),
// maps back to itself with its own depth, and, away from the surfaces' edges, its footprint lies in
// the plane of that surface.
TEST(TexelsView, FocusedTexelsLandOnTheScenesSurfacesAndMapBackToThemselves) {
    const Inspection in = inspect(box_on_plane(), "focused", 256);
    const DepthMap& surfaces = in.surface_depth();
    const std::vector<WorldTexel> texels = world_texels(in.setup, surfaces, 1);
    ASSERT_GT(texels.size(), 256u * 256u / 4);
    size_t off_surface = 0, not_back = 0, footprint_on_plane = 0;
    for (const WorldTexel& t : texels) {
        const ShadowMap& map = in.setup.maps[t.map];
        const glm::dvec3 uvz = world_to_uvz(map, t.centre);
        not_back += texel_of(map, glm::dvec2(uvz), in.resolution) != t.texel ||
                    std::abs(uvz.z - surfaces.at(t.texel.x, t.texel.y)) > 1e-6;
        const double across = glm::length(t.corners[2] - t.corners[0]);  // the footprint's diagonal
        const Nearest nearest = nearest_triangle(in.triangles, t.centre, 1e-3 * across);
        if (nearest.triangle < 0 || nearest.distance > 1e-3 * across) {
            ++off_surface;
            continue;
        }
        footprint_on_plane += std::all_of(t.corners.begin(), t.corners.end(), [&](const glm::dvec3& corner) {
            return distance_to_plane(in.triangles, nearest.triangle, corner) <= 1e-3 * across;
        });
    }
    EXPECT_EQ(not_back, 0u);
    EXPECT_EQ(off_surface, 0u);
    EXPECT_GE(footprint_on_plane, 0.95 * texels.size()) << "of " << texels.size() << " texels";
}

// At most the cap of texels is drawn, at the least stride that keeps to it, and the caption names it.
TEST(TexelsView, TheStrideCapsTheTexelsDrawnAndTheCaptionSaysIt) {
    const Inspection in = inspect(box_on_plane(), "focused", 1024);
    const DepthMap& surfaces = in.surface_depth();
    constexpr size_t kCap = 200'000;
    const int stride = texel_stride(in.setup, surfaces, kCap);
    ASSERT_GT(stride, 1) << "box_on_plane at 1024² holds more surface texels than the cap";
    EXPECT_LE(world_texels(in.setup, surfaces, stride).size(), kCap);
    EXPECT_GT(world_texels(in.setup, surfaces, stride - 1).size(), kCap) << "one map serves every texel";
    EXPECT_TRUE(
        any_contains(texts_of(in, view_or_throw("texels"), kWidth, kHeight), "every " + std::to_string(stride)));
}

TEST(TexelsView, EveryMapMethodDrawsTexelsAndATechniqueSaysItHasNone) {
    const Scene scene = box_on_plane();
    for (const Method& method : all_methods()) {
        const Inspection in = inspect(scene, method.name, 256);
        if (!in.has_map()) {
            EXPECT_TRUE(
                any_contains(texts_of(in, view_or_throw("texels"), kWidth, kHeight), "no shadow map, so no texels"))
                << method.name;
            continue;
        }
        EXPECT_GT(first_map_pixels(render_view(in, view_or_throw("texels"), {}, kWidth, kHeight)), 2000u)
            << method.name;
    }
}

// The border between the tiles runs down the texture's middle column (in the upper half the right
// tile's left edge, in the lower half the left tile's right edge); each tile is labelled. One map: no border.
TEST(ShadowMapView, AnAtlasShowsTheBorderBetweenItsTilesAndALabelEach) {
    const Scene scene = box_on_plane();
    const Inspection atlas = two_tile_atlas(scene, 1024);
    constexpr int kSide = 512;  // the 1024² texture fills the square: 2 texels a pixel, its middle at column 256
    const auto border_rows = [](const RgbImage& image, int from, int to) {
        int rows = 0;
        for (int y = 0; y < image.height - 40; ++y) {  // the caption's rows left out
            bool found = false;
            for (int x = from; x <= to && !found; ++x) found = has_colour(image.at(x, y), kTileBorder);
            rows += found;
        }
        return rows;
    };
    const RgbImage tiles = render_view(atlas, view_or_throw("shadowmap"), {}, kSide, kSide);
    EXPECT_GE(border_rows(tiles, kSide / 2 - 2, kSide / 2 + 1), 0.9 * (kSide - 40));
    EXPECT_LT(border_rows(tiles, kSide / 4 - 2, kSide / 4 + 1), 0.1 * kSide) << "no border inside a tile";
    const RgbImage one = render_view(inspect(scene, "uniform", 1024), view_or_throw("shadowmap"), {}, kSide, kSide);
    EXPECT_EQ(border_rows(one, 0, kSide - 1), 0);

    const std::vector<std::string> texts = texts_of(atlas, view_or_throw("shadowmap"), kSide, kSide);
    EXPECT_TRUE(any_contains(texts, "cascade 1\n512²"));
    EXPECT_TRUE(any_contains(texts, "cascade 2\n512²"));
}

// A cube map's faces, stored as 3 x 2, are shown unfolded as a cross in a texture four faces wide:
// the corner cells hold no face (white), the +y face above +z holds the ceiling beam (dark).
TEST(ShadowMapView, ACubeMapIsShownUnfoldedAsACross) {
    const Inspection cube = inspect(shipped_scene("lamp_room", 512, 512), "cube", 1024);
    constexpr int kSide = 512;  // the cross's texture, four faces wide, fills the square: cells of 128 pixels
    const RgbImage image = render_view(cube, view_or_throw("shadowmap"), {}, kSide, kSide);
    const auto white_share = [&](int column, int row) {
        int white = 0, all = 0;
        for (int y = row * 128 + 8; y < (row + 1) * 128 - 8; ++y)
            for (int x = column * 128 + 8; x < (column + 1) * 128 - 8; ++x, ++all)
                white += image.at(x, y)[0] == 255 && image.at(x, y)[1] == 255 && image.at(x, y)[2] == 255;
        return double(white) / all;
    };
    EXPECT_GT(white_share(0, 0), 0.99) << "no face in the cross's corner";
    EXPECT_GT(white_share(3, 2), 0.99);
    EXPECT_LT(white_share(1, 0), 0.9) << "+y: the beam over the bulb";
    const std::vector<std::string> texts = texts_of(cube, view_or_throw("shadowmap"), kSide, kSide);
    for (const char* face : {"face +x", "face -x", "face +y", "face -y", "face +z", "face -z"})
        EXPECT_TRUE(any_contains(texts, face)) << face;
    EXPECT_TRUE(any_contains(texts, "unfolded as a cross"));
}
