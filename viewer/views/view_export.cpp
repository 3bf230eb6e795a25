// A built view read back from its renderer as plain data (view_export.hpp): the cells of each
// actor's poly data by kind, a polygon as the fan of triangles VTK draws it as, a polyline as its
// segments; each cell's own colour, where the mapper shows one, carried to its points.
#include "views/view_export.hpp"

#include <cstdio>
#include <cstdlib>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkDataArray.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkProp.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include "views/offscreen_view.hpp"

namespace shadowlab {
namespace {

using nlohmann::json;

// Six significant digits: a page's float32 holds no more, and the text stays a third as long.
double rounded(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return std::strtod(text, nullptr);
}

json triple(const double* v) { return json::array({rounded(v[0]), rounded(v[1]), rounded(v[2])}); }

// One kind of cell (faces, lines or points) as flat point coordinates and, with cell colours, a
// colour per point.
struct CellsOut {
    json positions = json::array();
    json colours = json::array();

    void add(vtkPolyData* data, vtkIdType point, vtkDataArray* cell_colours, vtkIdType cell) {
        for (double c : triple(data->GetPoint(point))) positions.push_back(c);
        if (!cell_colours) return;
        double colour[3];
        cell_colours->GetTuple(cell, colour);
        const double scale = cell_colours->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
        for (double c : colour) colours.push_back(rounded(scale * c));
    }
    void write(json& shape, const char* kind, const char* colours_key) const {
        if (positions.empty()) return;
        shape[kind] = positions;
        if (!colours.empty()) shape[colours_key] = colours;
    }
};

// Each cell of `cells` (whose first cell has id `first_cell` in the poly data) as the points
// `emit` is given, in order.
template <class Emit>
vtkIdType for_each_cell(vtkCellArray* cells, vtkIdType first_cell, Emit&& emit) {
    vtkIdType cell = first_cell;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell) {
        vtkIdType size = 0;
        const vtkIdType* ids = nullptr;
        it->GetCurrentCell(size, ids);
        emit(cell, size, ids);
    }
    return cell;
}

json actor_shape(vtkActor* actor) {
    auto* data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInput());
    if (!data || data->GetNumberOfCells() == 0) return nullptr;
    vtkMapper* mapper = actor->GetMapper();
    vtkDataArray* cell_colours =
        mapper->GetScalarVisibility() ? data->GetCellData()->GetArray(mapper->GetArrayName()) : nullptr;
    if (cell_colours && cell_colours->GetNumberOfComponents() < 3) cell_colours = nullptr;
    CellsOut points, lines, faces;
    // VTK numbers the cells verts, lines, polygons, strips.
    vtkIdType cell = for_each_cell(data->GetVerts(), 0, [&](vtkIdType c, vtkIdType n, const vtkIdType* ids) {
        for (vtkIdType i = 0; i < n; ++i) points.add(data, ids[i], cell_colours, c);
    });
    cell = for_each_cell(data->GetLines(), cell, [&](vtkIdType c, vtkIdType n, const vtkIdType* ids) {
        for (vtkIdType i = 0; i + 1 < n; ++i)
            for (vtkIdType end : {ids[i], ids[i + 1]}) lines.add(data, end, cell_colours, c);
    });
    cell = for_each_cell(data->GetPolys(), cell, [&](vtkIdType c, vtkIdType n, const vtkIdType* ids) {
        for (vtkIdType i = 1; i + 1 < n; ++i)
            for (vtkIdType corner : {ids[0], ids[i], ids[i + 1]}) faces.add(data, corner, cell_colours, c);
    });
    for_each_cell(data->GetStrips(), cell, [&](vtkIdType c, vtkIdType n, const vtkIdType* ids) {
        for (vtkIdType i = 0; i + 2 < n; ++i)  // every other triangle of a strip turns the other way
            for (vtkIdType corner : {ids[i], ids[i + 1 + i % 2], ids[i + 2 - i % 2]})
                faces.add(data, corner, cell_colours, c);
    });
    vtkProperty* property = actor->GetProperty();
    json shape{{"colour", triple(property->GetColor())},
               {"opacity", rounded(property->GetOpacity())},
               {"line_width", rounded(property->GetLineWidth())},
               {"point_size", rounded(property->GetPointSize())},
               {"lit", property->GetLighting() && property->GetDiffuse() > 0.0}};
    faces.write(shape, "faces", "face_colours");
    lines.write(shape, "lines", "line_colours");
    points.write(shape, "points", "point_colours");
    return shape;
}

// A label pinned to a world point (views/world_label.cpp): a text actor placed beside a world
// coordinate. Other text (the caption, the legend) hangs from the viewport: the page has its own.
json pinned_label(vtkTextActor* text) {
    vtkCoordinate* anchor = text->GetPositionCoordinate()->GetReferenceCoordinate();
    if (!anchor || anchor->GetCoordinateSystem() != VTK_WORLD) return nullptr;
    return {{"at", triple(anchor->GetValue())},
            {"text", text->GetInput() ? text->GetInput() : ""},
            {"colour", triple(text->GetTextProperty()->GetColor())}};
}

json camera_of(vtkRenderer* renderer) {
    vtkCamera* camera = renderer->GetActiveCamera();
    return {{"position", triple(camera->GetPosition())},
            {"focal_point", triple(camera->GetFocalPoint())},
            {"view_up", triple(camera->GetViewUp())},
            {"parallel", camera->GetParallelProjection() != 0},
            {"parallel_scale", rounded(camera->GetParallelScale())},
            {"view_angle", rounded(camera->GetViewAngle())}};
}

}  // namespace

json exported_scene(vtkRenderer* renderer) {
    json shapes = json::array(), labels = json::array();
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor())
        if (actor->GetVisibility() && actor->GetMapper())
            if (json shape = actor_shape(actor); !shape.is_null()) shapes.push_back(std::move(shape));
    vtkPropCollection* props = renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp())
        if (auto* text = vtkTextActor::SafeDownCast(prop))
            if (json label = pinned_label(text); !label.is_null()) labels.push_back(std::move(label));
    return {{"background", triple(renderer->GetBackground())},
            {"camera", camera_of(renderer)},
            {"shapes", std::move(shapes)},
            {"labels", std::move(labels)}};
}

json exported_view(const Inspection& inspection, const View& view, const ViewOptions& options, int width, int height) {
    json scene;  // the window is only sized, never rendered
    with_offscreen_view(inspection, view, options, width, height,
                        [&](vtkRenderWindow*, vtkRenderer* renderer, const ViewReport& report) {
                            scene = exported_scene(renderer);
                            scene["legend"] = json::array();
                            for (const LegendEntry& entry : report.legend)
                                scene["legend"].push_back({{"colour", triple(&entry.colour[0])}, {"text", entry.text}});
                        });
    return scene;
}

}  // namespace shadowlab
