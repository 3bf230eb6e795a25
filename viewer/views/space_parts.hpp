#pragma once
// The pieces of the World, Light space and PPLS views (space_view.cpp), one concept per file: the
// space a view draws in and what it frames (space_frame.cpp), its camera presets (space_camera.cpp),
// the role colours (role_style.cpp), the canvas that draws and lists what it drew (space_canvas.cpp)
// with its legend (legend.cpp), the trace's steps (step_shapes.cpp) and the visible points the map
// misses (missed_points.cpp).
#include <optional>
#include <string>
#include <vector>

#include "views/view_parts.hpp"

namespace shadowlab {

// World -> `space`, as the method defined it (the camera's view matrix for a view space the trace
// lacks); nullopt when the method has no such space.
std::optional<glm::dmat4> world_to(const Inspection& in, Space space);

// The space one view draws in, and what its camera frames there.
struct SpaceFrame {
    Space space = Space::world;       // world, light, or ppls (the unit space for a map with no warp)
    glm::dmat4 from_world{1.0};       // world -> space, homogeneous
    Aabb region;                      // what matters: the scene (World), the body B (Light), the map's volume (PPLS)
    Aabb clip;                        // the region and a margin: nothing is drawn beyond it; the cameras frame it
    glm::dvec3 light{0, 0, 1};        // the light's direction in the space at the region's centre, unit
    glm::dvec3 view{0, 1, 0};         // the camera's view direction carried likewise, unit
    glm::dvec3 light_from, light_to;  // the light arrow, in the space
    bool atlas = false;  // the atlas of paraboloid or masked maps (unit_space_is_an_atlas): a picture, seen straight on

    // The region's middle extent: arrow heads and the axes are sized by it, so that one long axis (a
    // deep light box seen end-on) does not blow them up.
    double scale() const;
    double arrow_head() const { return 0.05 * scale(); }
    // Shapes of a space whose world-to-space matrix is `shape_from_world`, carried into this one.
    Placement placement_from(const glm::dmat4& shape_from_world) const;
};

// Paraboloid maps reach their atlas by no matrix, and maps sharing one texture in masks (a
// tetrahedron's faces) by one matrix each over the same square: their unit space is the atlas
// itself, holding the steps' discs or triangles alone; nothing of the world is carried there.
bool unit_space_is_an_atlas(const Inspection& in, Space space);

// The frame of the view drawing in `space` (world, light or ppls) showing the chosen step (null: none); nullopt when
// the method has no such space (a technique's Light space and PPLS).
std::optional<SpaceFrame> space_frame(const Inspection& in, Space space, const Step* chosen);

// Orthographic along the light or from the side of the light and view plane, or the oblique orbit.
void place_space_camera(vtkRenderer* renderer, const SpaceFrame& frame, SpacePreset preset, Space space);

// What a shape stands for fixes its colour and its legend line in every space view.
struct RoleStyle {
    glm::dvec3 colour;
    const char* legend;
};
const RoleStyle& role_style(Role role);
extern const glm::dvec3 kSpaceBackground;
glm::dvec3 dimmed(const glm::dvec3& colour);  // halfway to the background: an earlier step's shape
// A shape's colour and legend: its map's (a cascade's slice, box, tile: the Camera view's overlay
// colours, named as the views name maps) or its role's.
glm::dvec3 shape_colour(const NamedGeometry& g);
std::string shape_legend(const NamedGeometry& g, const ShadowSetup& setup);

// A swatch and a line of text per entry, down from the view's top-left corner (the caption is at the bottom).
void add_legend(vtkRenderer* renderer, const std::vector<LegendEntry>& entries);

struct Stroke {
    glm::dvec3 colour;
    double width = 1.5;    // lines, in pixels; points are twice as wide
    double opacity = 1.0;  // faces
};

// Draws into one space view and remembers what it drew, for the legend: an entry appears only once
// something of its kind is on screen.
class SpaceCanvas {
public:
    SpaceCanvas(vtkRenderer* renderer, const SpaceFrame& frame) : renderer_(renderer), frame_(frame) {}
    const SpaceFrame& frame() const { return frame_; }

    // Returns whether anything of it is left to draw after the cut to the frame's clip box.
    bool draw(const Placed& placed, const Stroke& stroke, const std::string& legend);
    // Text at a point of the space, facing the screen at a constant size.
    void label(const glm::dvec3& at, const std::string& text, const glm::dvec3& colour);
    void list(const glm::dvec3& colour, const std::string& legend);
    void finish() { add_legend(renderer_, legend_); }
    const std::vector<LegendEntry>& legend() const { return legend_; }

private:
    vtkRenderer* renderer_;
    SpaceFrame frame_;
    std::vector<LegendEntry> legend_;
};

// The trace's steps [from, to) (indices of Trace::steps), each in its own space carried into the
// canvas's: the chosen step bright in its roles' colours with its labels, the others dimmed.
void draw_steps(SpaceCanvas& canvas, const Inspection& in, size_t from, size_t to, size_t chosen);

// Points the camera sees (on a coarse image of its aspect) that the setup's maps leave outside [0,1]^3,
// and how many of them the exact reference puts in shadow: those the map wrongly leaves lit.
struct MissedPoints {
    std::vector<glm::dvec3> lit, in_shadow;
    size_t count() const { return lit.size() + in_shadow.size(); }
};
MissedPoints visible_points_missed(const Inspection& in);

}  // namespace shadowlab
