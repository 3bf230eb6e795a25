#pragma once
// Everything the views draw for one scene and method, computed once per change and shared by every
// view: the step trace, the scene's triangles, and the method's own result: for a map method its
// setup and every map rasterized into its tile of the texture; for a geometric technique its
// GeometryResult (verdicts, stencil polygons, counts). The exact reference and the error against
// it are traced only when a view asks for them, once per image size. No VTK here.
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "metrics/shadow_error.hpp"
#include "raster/depth_map.hpp"
#include "registry/method.hpp"
#include "scene/scene.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

struct InspectionRequest {
    std::string method = "focused";               // any name of the registry
    std::map<std::string, std::string> settings;  // key -> text, checked against the method's specs
    int resolution = 1024;                        // map texture texels per side
    double bias = -1.0;                           // world units along the light; < 0: slope-scaled per pixel
    int image_width = 640, image_height = 0;      // the camera image a technique judges, and the depth image
                                                  // visible depth bounds read (height 0: by aspect)
};

struct Inspection {
    Scene scene;
    const Method* method = nullptr;
    Settings settings;
    int resolution = 0;  // maps: texture texels per side
    double bias = -1.0;  // world units along the light; < 0: slope-scaled per pixel (slope_scaled_bias)
    int image_width = 0, image_height = 0;  // the camera image a technique was judged on, or the depth image read
    ShadowInputs inputs;
    Trace trace;
    WorldTriangles triangles;
    std::vector<bool> casters;  // per object
    ShadowSetup setup;          // maps: the method's result
    // A virtual map's pages kept from the inspection shown before this one (the window's page cache:
    // metrics/page_caching.hpp), per map of `setup`; empty when none was shown or none asked.
    std::vector<bool> pages_kept;
    ShadowLookup lookup;  // maps: the filter and bias the settings ask for (a constant `bias` replaces the bias)
    std::optional<GeometryResult> geometry;  // geometric techniques: the method's result

    bool has_map() const { return method->makes_maps(); }
    const std::string& name() const { return method->name; }
    const std::string& title() const { return method->title; }
    // What the user is told: a map method's fallbacks, or a technique's limits.
    const std::vector<Note>& notes() const { return has_map() ? setup.fallbacks : geometry->limits; }

    // Maps: every map of `setup` rasterized into its tile (on every core), stored in the lookup's
    // depth format, on the first call: the Camera view draws its own on the GPU, so a change pays for
    // the CPU's only when a view (Shadow map, Texels, Error) or a measure reads it. Made from `setup`
    // and `lookup.format` as they are at that first call.
    const DepthMap& depth() const;
    // The same with every object drawn, receivers too: where each texel lands on a surface (the
    // Texels view back-projects them).
    const DepthMap& surface_depth() const;

    // The exact reference of a width x height camera image (soft for an area light: light_reference),
    // traced on the first call for that size;
    // the last few sizes asked for stay (the Error view's, the light views' small one for missed points).
    const ReferenceImage& reference(int width, int height) const;
    // The result judged against reference(width, height): a map's verdicts and visibility read
    // through `lookup`, m and depth steps; a technique's verdicts.
    const ShadowError& error(int width, int height) const;

    // The lazy parts are made on first reading, by one thread at a time: the window's worker fills
    // them (views/view.hpp, prepare_view) before the GUI thread sees the inspection.
private:
    struct LazyDepth;  // a depth map, made once
    const DepthMap& lazily_rasterized(std::shared_ptr<LazyDepth>& lazy, const std::vector<bool>& drawn) const;
    mutable std::shared_ptr<LazyDepth> depth_, surface_depth_;
    struct Judged;  // the reference and error of one image size
    Judged& judged(int width, int height) const;
    mutable std::shared_ptr<std::deque<Judged>> judged_;  // most recently asked for first
};

// Throws std::invalid_argument naming the method, setting, resolution or image size at fault.
Inspection inspect_scene(const Scene& scene, const InspectionRequest& request);

}  // namespace shadowlab
