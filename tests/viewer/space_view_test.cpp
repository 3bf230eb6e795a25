// The World, Light space and PPLS views on their pixels (under Xvfb): every step of every method draws
// something the step before did not; from the light the map's volume is the map's square, from the
// side the warp turns the camera's frustum box-like; the scene in PPLS is optional and cut to the
// framed region; shapes are cut before the division by w; the visible points a map misses.
#include <algorithm>
#include <cmath>
#include <map>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "registry/method.hpp"
#include "scene/scene_loader.hpp"
#include "view_test_support.hpp"
#include "views/space_parts.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 640, kHeight = 480;
constexpr int kLegendRows = 56;  // the legend's swatches, in the shapes' colours, stand in the rows above this one
constexpr size_t kVisible = 30;  // pixels: a thin line a tenth of the picture across

// The shipped methods: those registered before any test runs (extension_test registers throw-away
// methods of its own while it runs, with no steps of their own to draw).
const std::vector<std::string> kShippedMethods = [] {
    std::vector<std::string> names;
    for (const Method& method : all_methods()) names.push_back(method.name);
    return names;
}();

Scene box_on_plane() { return shipped_scene("box_on_plane", kWidth, kHeight); }

Inspection inspect_shipped(const std::string& scene, const std::string& method) {
    InspectionRequest request;
    request.method = method;
    request.resolution = 256;
    request.image_width = kWidth;
    return inspect_scene(shipped_scene(scene, kWidth, kHeight), request);
}

Inspection inspect_box_on_plane(const std::string& method) { return inspect_shipped("box_on_plane", method); }

// Lines and points are drawn unlit: their pixels hold their colour exactly, up to rounding.
bool has_colour(const unsigned char* c, const glm::dvec3& colour) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(c[i] - 255.0 * colour[i]) > 6.0) return false;
    return true;
}

bool has_any(const unsigned char* c, const std::vector<glm::dvec3>& colours) {
    return std::any_of(colours.begin(), colours.end(), [&](const glm::dvec3& colour) { return has_colour(c, colour); });
}

std::vector<glm::dvec3> step_colours(const Step& step) {
    std::vector<glm::dvec3> colours;
    for (const NamedGeometry& g : step.geometry) colours.push_back(shape_colour(g));
    return colours;
}

// Pixels of the step's colours where the picture before held none of them (the legend's swatches left out).
size_t new_pixels(const RgbImage& now, const RgbImage* before, const std::vector<glm::dvec3>& colours) {
    size_t count = 0;
    for (int y = kLegendRows; y < now.height; ++y)
        for (int x = 0; x < now.width; ++x)
            count += has_any(now.at(x, y), colours) && !(before && has_any(before->at(x, y), colours));
    return count;
}

// The view that draws a step's space; a geometric technique draws every step in the World.
const View& view_of(const Inspection& in, Space space) {
    if (!in.has_map() || space == Space::world || space == Space::view) return view_or_throw("world");
    return space == Space::light ? view_or_throw("light") : view_or_throw("ppls");
}

// The first and last columns (rows) where a colour runs along at least `share` of the picture's
// height (width): the straight edges of an axis-aligned rectangle; -1 where none does.
struct Span {
    int first = -1, last = -1;
    int length() const { return last - first; }
};
Span straight_edges(const RgbImage& image, const glm::dvec3& colour, bool columns, double share) {
    const int lines = columns ? image.width : image.height, along = columns ? image.height : image.width;
    Span span;
    for (int i = columns ? 0 : kLegendRows; i < lines; ++i) {
        int run = 0;
        for (int j = columns ? kLegendRows : 0; j < along; ++j)
            run += has_colour(columns ? image.at(i, j) : image.at(j, i), colour);
        if (run < share * along) continue;
        if (span.first < 0) span.first = i;
        span.last = i;
    }
    return span;
}

// How much wider the drawn camera frustum is at one end than at the other: its pixels measured
// across their principal axis (the frustum's length, however the view direction lies on screen),
// within the first and the last tenth along it.
double frustum_end_ratio(const RgbImage& image) {
    const glm::dvec3 frustum = role_style(Role::view).colour;
    std::vector<glm::dvec2> pixels;
    for (int y = kLegendRows; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (has_colour(image.at(x, y), frustum)) pixels.push_back({x, y});
    if (pixels.size() < 2) return 0.0;
    glm::dvec2 mean(0.0);
    for (const glm::dvec2& p : pixels) mean += p / static_cast<double>(pixels.size());
    double xx = 0.0, xy = 0.0, yy = 0.0;
    for (const glm::dvec2& p : pixels)
        xx += (p.x - mean.x) * (p.x - mean.x), xy += (p.x - mean.x) * (p.y - mean.y),
            yy += (p.y - mean.y) * (p.y - mean.y);
    const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);  // the covariance's principal direction
    const glm::dvec2 along(std::cos(angle), std::sin(angle)), across(-along.y, along.x);
    double t_min = 1e300, t_max = -1e300;
    for (const glm::dvec2& p : pixels)
        t_min = std::min(t_min, glm::dot(p, along)), t_max = std::max(t_max, glm::dot(p, along));
    auto width_at = [&](double from, double to) {
        double lo = 1e300, hi = -1e300;
        for (const glm::dvec2& p : pixels)
            if (const double t = glm::dot(p, along); t >= from && t <= to)
                lo = std::min(lo, glm::dot(p, across)), hi = std::max(hi, glm::dot(p, across));
        return std::max(1.0, hi - lo);
    };
    const double tenth = 0.1 * (t_max - t_min);
    const double a = width_at(t_min, t_min + tenth), b = width_at(t_max - tenth, t_max);
    return std::max(a, b) / std::min(a, b);
}

}  // namespace

// A step's idea is on screen: in the view of its space, pixels of its roles' colours appear that the
// previous step's picture in the same view did not have (the first step: that its colours show). On
// the teaching scene, whose shadows fall beside their casters where the World view sees them.
TEST(SpaceViews, EveryStepOfEveryMethodDrawsSomethingNew) {
    for (const std::string& method : kShippedMethods) {
        const Inspection in = inspect_shipped("teaching", method);
        const std::vector<Step>& steps = in.trace.steps();
        std::map<std::pair<size_t, std::string>, RgbImage> renders;
        auto render = [&](size_t i, const View& view) -> const RgbImage& {
            auto [it, fresh] = renders.try_emplace({i, view.name});
            if (fresh) it->second = render_view(in, view, ViewOptions{.step = steps[i].id}, kWidth, kHeight);
            return it->second;
        };
        for (size_t i = 0; i < steps.size(); ++i) {
            const View& view = view_of(in, steps[i].space);
            const RgbImage* before = i == 0 ? nullptr : &render(i - 1, view);
            EXPECT_GE(new_pixels(render(i, view), before, step_colours(steps[i])), kVisible)
                << method << ": step " << i + 1 << " '" << steps[i].id << "' draws nothing new in the " << view.name
                << " view";
        }
    }
}

// From the light, the uniform map's volume is the map's own square: axis-aligned (its edges run
// straight down columns and along rows) and filling most of the picture, in Light space and in its
// unit space (its PPLS: no warp).
TEST(SpacePresets, FromTheLightTheMapsVolumeIsAnAxisAlignedRectangleFillingTheFrame) {
    const Inspection in = inspect_box_on_plane("uniform");
    const glm::dvec3 cyan = role_style(Role::map).colour;
    for (const View* view : {&view_or_throw("light"), &view_or_throw("ppls")}) {
        const RgbImage image =
            render_view(in, *view, {.step = "unit-cube", .preset = SpacePreset::from_light}, kWidth, kHeight);
        const Span columns = straight_edges(image, cyan, true, 0.3), rows = straight_edges(image, cyan, false, 0.3);
        ASSERT_GE(columns.first, 0) << view->name << ": no straight vertical edge";
        ASSERT_GE(rows.first, 0) << view->name << ": no straight horizontal edge";
        EXPECT_GT(columns.length(), kHeight / 2) << view->name;
        EXPECT_GT(rows.length(), kHeight / 2) << view->name;
        EXPECT_GT(columns.length() * rows.length(), 0.3 * kWidth * kHeight) << view->name;
    }
}

// From the side, LiSPSM's warp shows: in Light space the camera's frustum opens from its near end to
// its far end; in PPLS, after the perspective warp, its ends are nearly as wide as each other.
TEST(SpacePresets, FromTheSideTheWarpTurnsTheFrustumBoxLike) {
    const Inspection in = inspect_box_on_plane("lispsm");
    const ViewOptions before_warp{.step = "light-space", .preset = SpacePreset::side};
    const ViewOptions after_warp{.step = "warp", .preset = SpacePreset::side};
    const double light_space = frustum_end_ratio(render_view(in, view_or_throw("light"), before_warp, kWidth, kHeight));
    const double ppls = frustum_end_ratio(render_view(in, view_or_throw("ppls"), after_warp, kWidth, kHeight));
    EXPECT_GT(light_space, 4.0) << "from its apex (near the eye) the frustum opens";
    EXPECT_LT(ppls, 2.0) << "the warp brings its ends close to one width";
    EXPECT_GT(light_space, 3.0 * ppls);
}

// The scene in PPLS is optional, and when drawn it is cut to the map's volume and the margin
// around it: seen from the light, no pixel of it lies beyond the margin around the volume's square.
TEST(PplsView, SceneIsOptionalAndCutToTheFramedRegion) {
    const Inspection in = inspect_box_on_plane("lispsm");
    const RgbImage with =
        render_view(in, view_or_throw("ppls"), {.step = "warp", .preset = SpacePreset::from_light}, kWidth, kHeight);
    const RgbImage without =
        render_view(in, view_or_throw("ppls"),
                    {.step = "warp", .preset = SpacePreset::from_light, .scene_in_ppls = false}, kWidth, kHeight);
    const std::optional<SpaceFrame> frame = space_frame(in, Space::ppls, in.trace.find("warp"));
    ASSERT_TRUE(frame);
    // The map's volume is the region: its square's pixels give the scale of the margin.
    const glm::dvec3 cyan = role_style(Role::map).colour;
    const Span columns = straight_edges(with, cyan, true, 0.3), rows = straight_edges(with, cyan, false, 0.3);
    ASSERT_GE(columns.first, 0);
    ASSERT_GE(rows.first, 0);
    const double pixels_per_unit = columns.length() / frame->region.extent().x;
    const double margin_x = (frame->clip.max.x - frame->region.max.x) * pixels_per_unit + 2.0;
    const double margin_y = (frame->clip.max.y - frame->region.max.y) * pixels_per_unit + 2.0;
    size_t scene_pixels = 0, beyond = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const unsigned char *a = with.at(x, y), *b = without.at(x, y);
            if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) < 12) continue;
            ++scene_pixels;
            beyond += x < columns.first - margin_x || x > columns.last + margin_x || y < rows.first - margin_y ||
                      y > rows.last + margin_y;
        }
    EXPECT_GT(scene_pixels, kWidth * kHeight / 20u) << "the scene is drawn when asked for";
    EXPECT_EQ(beyond, 0u);
}

// Shapes are cut in homogeneous space: a ground plane crossing w = 0 under a perspective frame keeps
// every drawn point inside the clip box, instead of flying off toward infinity.
TEST(Polydata, ShapesAreCutToTheClipBoxBeforeTheDivision) {
    const Scene scene = box_on_plane();
    const WorldTriangles triangles = tessellate(scene);
    const glm::dmat4 to_space = glm::perspective(glm::radians(60.0), 1.0, 0.1, 100.0) *
                                glm::lookAt(glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(0.0, 1.0, -1.0), glm::dvec3(0, 1, 0));
    const Aabb clip{glm::dvec3(-2.0), glm::dvec3(2.0)};
    const Placed placed = triangles_polydata(triangles, std::vector<bool>(scene.objects.size(), true),
                                             object_colours(scene), Placement{.to_space = to_space, .clip = clip});
    ASSERT_GT(placed.data->GetNumberOfPolys(), 0);
    for (vtkIdType i = 0; i < placed.data->GetNumberOfPoints(); ++i) {
        double p[3];
        placed.data->GetPoint(i, p);
        EXPECT_TRUE(clip.contains({p[0], p[1], p[2]}, 1e-6)) << p[0] << ", " << p[1] << ", " << p[2];
    }
}

// The marks: a focused map covers every visible receiver of the scene (all it sees), so it misses
// none; the same map squeezed to the middle half of its square misses the points around it.
TEST(MissedPointMarks, NoneWhereTheMapCoversEverythingVisible) {
    const Inspection in = inspect_box_on_plane("focused");
    EXPECT_EQ(visible_points_missed(in).count(), 0u);
    Inspection squeezed = in;
    glm::dmat4& uvz = squeezed.setup.maps.at(0).world_to_uvz;
    for (int row = 0; row < 2; ++row)  // u' = 2u - 1/2 (and v): the rows of u w and v w become 2 u w - w / 2
        for (int column = 0; column < 4; ++column) uvz[column][row] = 2.0 * uvz[column][row] - 0.5 * uvz[column][3];
    EXPECT_GT(visible_points_missed(squeezed).count(), 0u);
}
