#pragma once
// A view's 3D picture as data that a web page draws again (`lesson --interactive`): the view is
// built as for `render`, and what it put in the renderer is read back, not computed anew. Every
// actor's poly data as the view placed and cut it in its space (faces, lines, points, each cell's
// colour), its opacity, line width and whether it is lit; the labels pinned to points; the camera
// the view placed; the background. No render: nothing here needs the GPU.
#include <nlohmann/json.hpp>

#include "views/view.hpp"

class vtkRenderer;

namespace shadowlab {

// The 3D props of a built renderer:
//   {"background": [r, g, b], "camera": {"position", "focal_point", "view_up": [x, y, z],
//    "parallel": bool, "parallel_scale", "view_angle" (degrees, vertical)},
//    "shapes": [{"faces": [x, y, z, ...] (3 points a triangle), "lines": [...] (2 a segment),
//                "points": [...], "face_colours" / "line_colours" / "point_colours": [r, g, b, ...]
//                (one per point, when the cells carry their own), "colour": [r, g, b],
//                "opacity", "line_width", "point_size" (pixels), "lit": bool}],
//    "labels": [{"at": [x, y, z], "text", "colour": [r, g, b]}]}
// Colours are in [0, 1]; coordinates are the view's space, rounded to 6 significant digits.
nlohmann::json exported_scene(vtkRenderer* renderer);

// The view built for the inspection into a renderer of width x height (the presets frame by its
// aspect) and exported, with what its legend lists: "legend": [{"colour": [r, g, b], "text"}].
nlohmann::json exported_view(const Inspection& inspection, const View& view, const ViewOptions& options, int width,
                             int height);

}  // namespace shadowlab
