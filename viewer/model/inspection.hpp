#pragma once
// Everything the views draw for one scene and method, computed once and shared by every view: the
// step trace and the scene's triangles; for a map method its setup and the first map rasterized on
// the CPU, for a geometric technique (volumes, planar) its verdicts and stencil polygons instead.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "methods/method.hpp"
#include "model/technique_inspection.hpp"
#include "raster/depth_map.hpp"
#include "scene/scene.hpp"
#include "scene/tessellation.hpp"

namespace shadowlab {

struct InspectionRequest {
    std::string method = "focused";                // a map method or a technique
    std::map<std::string, std::string> settings;  // key -> text, checked against the method's specs
    int resolution = 1024;                        // map texels per side
    double bias = -1.0;  // world units along the light; < 0: slope-scaled per pixel
    int image_width = 640, image_height = 0;  // the camera image a technique judges (height 0: by aspect)
};

struct Inspection {
    Scene scene;
    const Method* method = nullptr;              // a map method, or
    std::optional<TechniqueInspection> technique;  // a geometric technique (then no setup, map or depth)
    Settings settings;
    int resolution = 0;
    double bias = -1.0;  // world units along the light; < 0: slope-scaled per pixel (slope_scaled_bias)
    ShadowInputs inputs;
    ShadowSetup setup;
    Trace trace;
    WorldTriangles triangles;
    std::vector<bool> casters;  // per object
    DepthMap depth;             // setup.maps.front(), rasterized

    bool has_map() const { return method != nullptr; }
    const ShadowMap& map() const { return setup.maps.front(); }  // only with has_map()
    const std::string& name() const { return method ? method->name : technique->technique->name; }
    const std::string& title() const { return method ? method->title : technique->technique->title; }
    const std::optional<std::string>& fallback() const { return method ? setup.fallback : technique->result.fallback; }
};

// Throws std::invalid_argument naming the method (or technique), setting or resolution at fault.
Inspection inspect_scene(const Scene& scene, const InspectionRequest& request);

}  // namespace shadowlab
