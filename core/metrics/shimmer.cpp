#include "metrics/shimmer.hpp"

#include <optional>
#include <stdexcept>

#include "math/parallel_rows.hpp"
#include "lookup/shadow_reader.hpp"
#include "raster/depth_map.hpp"
#include "reference/camera_depth_image.hpp"
#include "reference/visible_depths.hpp"

namespace shadowlab {
namespace {

// Inside the camera's view volume: within its clip space's -w..w on every axis.
bool in_view(const glm::dmat4& clip_from_world, const glm::dvec3& p) {
    const glm::dvec4 c = clip_from_world * glm::dvec4(p, 1.0);
    return c.w > 0.0 && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w;
}

constexpr signed char kNotJudged = -1;

// Each sample's verdict under the frame's maps: 1 in shadow (visibility below one half), 0 lit,
// kNotJudged outside the view.
std::vector<signed char> verdicts(const std::vector<ShimmerSample>& samples, const Camera& camera,
                                  const ShadowReader& reader, const std::optional<CameraDepthImage>& depths) {
    const glm::dmat4 clip_from_world = camera.projection_matrix() * camera.view_matrix();
    std::vector<signed char> out(samples.size(), kNotJudged);
    parallel_rows([&](int first, int stride) {
        for (size_t i = first; i < samples.size(); i += stride) {
            const ShimmerSample& s = samples[i];
            if (!in_view(clip_from_world, s.position)) continue;
            const double v = reader.visibility({.position = s.position, .normal = s.normal});
            const ContactShadow& contact = reader.lookup().contact;
            out[i] = (depths ? with_contact_shadow(v, contact, *depths, reader.light(), s.position) : v) < 0.5;
        }
    });
    return out;
}

// The frame's inputs; the visible depths, when the settings read them, from the frame's own depth
// image at the reference's size (the camera moved: what it sees changed).
ShadowInputs frame_inputs(const MeasureContext& c, const Method& method, const Settings& settings, const Camera& camera,
                          int resolution) {
    ShadowInputs inputs = gather_inputs(camera, c.scene.light, c.boxes);
    inputs.texture_resolution = resolution;
    if (method.wants_visible_depths(settings)) {
        Scene seen_from_frame = c.scene;
        seen_from_frame.camera = camera;
        trace_depth_image(inputs, seen_from_frame, c.triangles, c.reference.width, c.reference.height);
    }
    return inputs;
}

// Contact shadows march in the frame's own depth image (what the camera sees from there), traced
// at the reference's size; none when they are off.
std::optional<CameraDepthImage> frame_depth_image(const MeasureContext& c, const ShadowLookup& lookup,
                                                  const Camera& camera) {
    if (!lookup.contact.on()) return std::nullopt;
    Scene seen_from_frame = c.scene;
    seen_from_frame.camera = camera;
    return camera_depth_image(camera,
                              visible_points(seen_from_frame, c.triangles, c.reference.width, c.reference.height));
}

}  // namespace

std::vector<ShimmerSample> shimmer_samples(const MeasureContext& c) {
    const ReferenceImage& ref = c.reference;
    std::vector<ShimmerSample> samples;
    for (size_t i = 0; i < ref.visible.size(); ++i)
        if (ref.visible[i] && ref.facing[i] > 0.0f && c.scene.objects[ref.object[i]].receives)
            samples.push_back({ref.position[i], ref.normal[i], ref.lit[i] != 0});
    return samples;
}

size_t Shimmer::flips() const {
    size_t n = 0;
    for (const FrameShimmer& f : frames) n += f.flips;
    return n;
}

size_t Shimmer::transitions() const {
    size_t n = 0;
    for (const FrameShimmer& f : frames) n += f.transitions;
    return n;
}

namespace {
double per_frame_after_the_first(const std::vector<FrameShimmer>& frames, double FrameShimmer::*texels) {
    double sum = 0.0;
    for (std::size_t i = 1; i < frames.size(); ++i) sum += frames[i].*texels;
    return frames.size() > 1 ? sum / double(frames.size() - 1) : 0.0;
}
}  // namespace

double Shimmer::texels_fresh_per_frame() const {
    return per_frame_after_the_first(frames, &FrameShimmer::texels_fresh);
}
double Shimmer::texels_cached_per_frame() const {
    return per_frame_after_the_first(frames, &FrameShimmer::texels_cached);
}

double Shimmer::share() const { return transitions() ? static_cast<double>(flips()) / transitions() : 0.0; }

Shimmer measure_shimmer(const MeasureContext& c, const std::vector<ShimmerSample>& samples, const Method& method,
                        const Settings& settings, int resolution, double bias, const CameraPath& path) {
    if (!method.makes_maps())
        throw std::invalid_argument("shimmer: " + method.name + " is a geometric technique: it has no map to shimmer");
    const ShadowLookup lookup = lookup_from(settings, bias);
    Shimmer shimmer;
    std::vector<signed char> before;
    std::optional<ShadowSetup> previous;
    for (int frame = 0; frame < path.frames; ++frame) {
        const Camera camera = camera_at(c.scene.camera, path, frame);
        const ShadowSetup setup =
            method.compute_maps(frame_inputs(c, method, settings, camera, resolution), settings, nullptr);
        const DepthMap depth = rasterize_depth(c.triangles, c.casters, setup, resolution, lookup.format);
        const ShadowReader reader(setup, depth, c.scene.light, lookup);
        const std::vector<signed char> now = verdicts(samples, camera, reader, frame_depth_image(c, lookup, camera));
        const PageTurnover pages = page_turnover(previous ? &*previous : nullptr, setup);
        FrameShimmer f{.frame = frame,
                       .fallbacks = setup.fallbacks,
                       .pages = pages,
                       .texels_fresh = texels_in_tiles(setup, resolution),
                       .texels_cached = texels_drawn(setup, pages, resolution)};
        for (size_t i = 0; i < samples.size(); ++i) {
            if (now[i] == kNotJudged) continue;
            ++f.judged;
            f.wrong += (now[i] == 1) == samples[i].lit;
            if (before.empty() || before[i] == kNotJudged) continue;
            ++f.transitions;
            f.flips += now[i] != before[i];
        }
        shimmer.frames.push_back(std::move(f));
        before = now;
        previous = setup;
    }
    return shimmer;
}

}  // namespace shadowlab
