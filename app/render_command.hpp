#pragma once
// `shadowlab render SCENE --method M [--view V] [--step ID] [--size WxH] [--resolution N] [--bias B]
//  [--aliasing total|perspective|projection] [--error auto|verdicts|signed] [--texture depth|mean|deviation]
//  [--light AZ,EL] [--preset orbit|light|side] [--overlay none|cascade|texels] [--no-scene-in-ppls] --out FILE.png`
#include <map>
#include <string>

#include "render/rgb_image.hpp"
#include "scene_source.hpp"

namespace shadowlab {

struct RenderOptions {
    std::string scene_file;
    SceneSource scene_source;  // which of the scene file's cameras and lights, or an engine's camera
    std::string method = "focused";
    std::map<std::string, std::string> settings;
    std::string view = "camera";
    std::string step;  // empty: the method's last step
    int width = 1280, height = 720;
    int resolution = 2048;
    double bias = -1.0;              // world units along the light; < 0: automatic
    std::string aliasing = "total";  // the Error view's heat map: m, or its perspective or projection factor
    std::string error = "auto";      // the Error view: verdicts, signed visibility error, or auto (signed if soft)
    std::string texture = "depth";   // the Shadow map view: depth, or the moments' mean or deviation (vsm, evsm)
    std::string
        light;  // "AZ,EL" in degrees, as the window's Controls panel: the light's new direction; empty: the scene's
    std::string preset = "orbit";  // World, Light space, PPLS: how the camera looks (space_preset_named)
    bool scene_in_ppls = true;     // PPLS: draw the scene's triangles
    std::string overlay =
        "none";  // Camera view of a map method: none, cascade (each surface's map) or texels (per pixel)
    std::string out;
};

// The view of `scene` drawn offscreen as `options` ask (not their scene file or out); notes and
// fallbacks go to stderr. Throws on bad input, std::runtime_error without an X display. The Python
// module's render is this call.
RgbImage render_image(Scene scene, const RenderOptions& options);

// Draws the view offscreen and writes the PNG; notes and fallbacks go to stderr. Throws on bad input.
void run_render(const RenderOptions& options);

}  // namespace shadowlab
