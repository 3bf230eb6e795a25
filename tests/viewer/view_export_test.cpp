// A view read back from its renderer for the interactive lesson (views/view_export.hpp): every cell
// the view's actors hold reaches the page, in the view's space and cut to its clip box as the view
// cut it, each cell's own colour on its points; the labels, the camera and the legend are the view's.
#include <gtest/gtest.h>
#include <string>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include "scene/scene_loader.hpp"
#include "views/offscreen_view.hpp"
#include "views/space_parts.hpp"
#include "views/view_export.hpp"

using namespace shadowlab;
using nlohmann::json;

namespace {

const std::string kScene = std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json";

// What VTK draws of the cells: points of vertex cells, segments of polylines, triangles of polygons' fans.
struct CellCounts {
    size_t points = 0, segments = 0, triangles = 0, shapes = 0;
};

size_t sum_over(vtkCellArray* cells, vtkIdType less) {
    size_t sum = 0;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell()) {
        vtkIdType size = 0;
        const vtkIdType* ids = nullptr;
        it->GetCurrentCell(size, ids);
        sum += static_cast<size_t>(std::max<vtkIdType>(size - less, 0));
    }
    return sum;
}

CellCounts actors_cells(vtkRenderer* renderer) {
    CellCounts counts;
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor()) {
        auto* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
        if (!data || data->GetNumberOfCells() == 0) continue;
        ++counts.shapes;
        counts.points += sum_over(data->GetVerts(), 0);
        counts.segments += sum_over(data->GetLines(), 1);
        counts.triangles += sum_over(data->GetPolys(), 2);
    }
    return counts;
}

CellCounts exported_cells(const json& scene) {
    CellCounts counts{.shapes = scene["shapes"].size()};
    for (const json& shape : scene["shapes"]) {
        counts.points += shape.value("points", json::array()).size() / 3;
        counts.segments += shape.value("lines", json::array()).size() / 6;
        counts.triangles += shape.value("faces", json::array()).size() / 9;
    }
    return counts;
}

// Every coordinate the page draws (cells and labels), as points of the space.
std::vector<glm::dvec3> drawn_points(const json& scene) {
    std::vector<glm::dvec3> points;
    for (const json& shape : scene["shapes"])
        for (const char* kind : {"faces", "lines", "points"})
            if (shape.contains(kind))
                for (size_t i = 0; i + 2 < shape[kind].size(); i += 3)
                    points.emplace_back(shape[kind][i], shape[kind][i + 1], shape[kind][i + 2]);
    for (const json& label : scene["labels"]) points.emplace_back(label["at"][0], label["at"][1], label["at"][2]);
    return points;
}

struct Case {
    const char* method;
    const char* view;
    const char* step;
    Space space;
    SpacePreset preset;
};

}  // namespace

TEST(ViewExport, EveryCellTheViewHoldsReachesThePageInsideTheViewsClipBox) {
    for (const Case& c : {Case{"lispsm", "world", "frustum", Space::world, SpacePreset::orbit},
                          Case{"lispsm", "ppls", "warp", Space::ppls, SpacePreset::side},
                          Case{"xpsm", "ppls", "xpsm-13", Space::ppls, SpacePreset::from_light}}) {
        SCOPED_TRACE(std::string(c.method) + " " + c.view + " " + c.step);
        const Inspection in = inspect_scene(load_scene(kScene), {.method = c.method, .resolution = 256});
        const Step* step = in.trace.find(c.step);
        ASSERT_NE(step, nullptr);
        const ViewOptions options{.step = c.step, .preset = c.preset};
        json scene;
        CellCounts drawn;
        double camera_position[3];
        std::vector<LegendEntry> legend;
        with_offscreen_view(in, view_or_throw(c.view), options, 320, 200,
                            [&](vtkRenderWindow*, vtkRenderer* renderer, const ViewReport& report) {
                                scene = exported_scene(renderer);
                                drawn = actors_cells(renderer);
                                renderer->GetActiveCamera()->GetPosition(camera_position);
                                legend = report.legend;
                            });
        const CellCounts exported = exported_cells(scene);
        ASSERT_GT(drawn.shapes, 0u);
        EXPECT_EQ(exported.shapes, drawn.shapes);
        EXPECT_EQ(exported.points, drawn.points);
        EXPECT_EQ(exported.segments, drawn.segments);
        EXPECT_EQ(exported.triangles, drawn.triangles);
        EXPECT_GT(exported.segments, 0u);
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_NEAR(scene["camera"]["position"][axis].get<double>(), camera_position[axis],
                        1e-5 * std::abs(camera_position[axis]) + 1e-9);

        // The view cut every shape to its clip box: so are the page's points, to their 6 digits.
        const std::optional<SpaceFrame> frame = space_frame(in, c.space, step);
        ASSERT_TRUE(frame);
        const double slack = 1e-5 * glm::length(frame->clip.extent());
        const std::vector<glm::dvec3> points = drawn_points(scene);
        ASSERT_FALSE(points.empty());
        size_t outside = 0;
        for (const glm::dvec3& p : points)
            outside += glm::any(glm::lessThan(p, frame->clip.min - slack)) ||
                       glm::any(glm::greaterThan(p, frame->clip.max + slack));
        EXPECT_EQ(outside, 0u) << "of " << points.size();

        bool light_label = false;
        for (const json& label : scene["labels"]) light_label |= label["text"] == "light";
        EXPECT_TRUE(light_label);
        ASSERT_FALSE(legend.empty());
        EXPECT_EQ(exported_view(in, view_or_throw(c.view), options, 320, 200)["legend"].size(), legend.size());
    }
}

// The scene's triangles carry each object's colour per cell (views/polydata.cpp): on the page each
// triangle's three points get its colour, in [0, 1].
TEST(ViewExport, ACellsOwnColourGoesToEachOfItsPoints) {
    const Inspection in = inspect_scene(load_scene(kScene), {.method = "lispsm", .resolution = 256});
    const json scene = exported_view(in, view_or_throw("world"), {.step = "frustum"}, 320, 200);
    size_t coloured = 0;
    for (const json& shape : scene["shapes"]) {
        if (!shape.contains("face_colours")) continue;
        ++coloured;
        ASSERT_EQ(shape["face_colours"].size(), shape["faces"].size());
        const json& colours = shape["face_colours"];
        for (size_t i = 0; i < colours.size(); ++i) {
            EXPECT_GE(colours[i].get<double>(), 0.0);
            EXPECT_LE(colours[i].get<double>(), 1.0);
            if (i % 9 < 3) {
                EXPECT_EQ(colours[i], colours[i + 3]) << "a triangle's points differ in colour";
            }
        }
    }
    EXPECT_EQ(coloured, 1u) << "the scene's triangles";
}
