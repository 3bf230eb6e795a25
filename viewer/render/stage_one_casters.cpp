#include "render/stage_one_casters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtkUnsignedCharArray.h>
#include <vtk_glew.h>

namespace shadowlab {
namespace {

constexpr const char* kUvAttribute = "shadowCasterUv";

// Points whose coordinates reach the shaders unchanged (no VBO shift: MC is the setup's coordinates).
vtkSmartPointer<vtkActor> actor_of(vtkPolyData* data) {
    vtkNew<vtkOpenGLPolyDataMapper> mapper;
    mapper->SetInputData(data);
    mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
    if (data->GetPointData()->GetArray(kUvAttribute))
        mapper->MapDataArrayToVertexAttribute(kUvAttribute, kUvAttribute, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
}

// The chosen triangles sharing the mesh's vertices.
vtkSmartPointer<vtkActor> opaque_actor(const WorldTriangles& triangles, const std::vector<std::size_t>& chosen) {
    vtkNew<vtkPoints> points;
    for (const glm::dvec3& v : triangles.vertices) points->InsertNextPoint(v.x, v.y, v.z);
    vtkNew<vtkCellArray> cells;
    for (std::size_t i : chosen) {
        const std::array<int, 3>& t = triangles.triangles[i];
        const vtkIdType corners[3] = {t[0], t[1], t[2]};
        cells->InsertNextCell(3, corners);
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetPolys(cells);
    return actor_of(data);
}

// A triangle's corners' texture coordinates: its alpha test's or its base colour's (the same TEXCOORD_0).
const std::array<glm::dvec2, 3>& uv_of(const WorldTriangles& triangles, std::size_t i) {
    return triangles.alpha_tested() && triangles.alpha[i].test ? triangles.alpha[i].uv : triangles.colour.at(i).uv;
}

// The chosen triangles, three vertices each with their corners' texture coordinates.
vtkSmartPointer<vtkPolyData> textured_polydata(const WorldTriangles& triangles,
                                               const std::vector<std::size_t>& chosen) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkFloatArray> uv;
    uv->SetName(kUvAttribute);
    uv->SetNumberOfComponents(2);
    vtkNew<vtkCellArray> cells;
    for (std::size_t i : chosen) {
        vtkIdType corners[3];
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& v = triangles.vertices[triangles.triangles[i][k]];
            corners[k] = points->InsertNextPoint(v.x, v.y, v.z);
            const glm::dvec2& corner = uv_of(triangles, i)[k];
            uv->InsertNextTuple2(corner.x, corner.y);
        }
        cells->InsertNextCell(3, corners);
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(cells);
    data->GetPointData()->AddArray(uv);
    return data;
}

// The triangles passing `keep`, grouped by alpha test: the untested ones (when `untested` is set)
// under a null test first, then each test's in the order of its first triangle.
template <class Keep>
std::vector<std::pair<std::shared_ptr<const AlphaTest>, std::vector<std::size_t>>> by_alpha_test(
    const WorldTriangles& triangles, Keep keep) {
    std::vector<std::pair<std::shared_ptr<const AlphaTest>, std::vector<std::size_t>>> groups{{nullptr, {}}};
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i) {
        if (!keep(i)) continue;
        const std::shared_ptr<const AlphaTest>& test = triangles.alpha_tested() ? triangles.alpha[i].test : nullptr;
        auto group = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == test; });
        if (group == groups.end()) group = groups.insert(groups.end(), {test, {}});
        group->second.push_back(i);
    }
    return groups;
}

}  // namespace

std::vector<CasterActor> caster_actors(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object) {
    std::vector<CasterActor> out;
    for (const auto& [test, chosen] :
         by_alpha_test(triangles, [&](std::size_t i) { return casts_per_object.at(triangles.object[i]); })) {
        if (chosen.empty()) continue;
        out.push_back({.actor = test ? actor_of(textured_polydata(triangles, chosen)) : opaque_actor(triangles, chosen),
                       .alpha = test});
    }
    return out;
}

bool has_material(const WorldTriangles& triangles, std::size_t triangle) {
    return (triangles.alpha_tested() && triangles.alpha[triangle].test) ||
           (triangles.coloured() && triangles.colour[triangle].colour);
}

std::vector<CasterActor> material_surfaces(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                                           const std::vector<glm::dvec3>& colours_per_object) {
    struct Group {
        CasterActor surface;
        std::vector<std::size_t> chosen;
    };
    std::vector<Group> groups;
    for (std::size_t i = 0; i < triangles.triangles.size(); ++i) {
        if (!has_material(triangles, i)) continue;
        const std::shared_ptr<const AlphaTest> alpha = triangles.alpha_tested() ? triangles.alpha[i].test : nullptr;
        const std::shared_ptr<const BaseColour> colour = triangles.coloured() ? triangles.colour[i].colour : nullptr;
        const CasterActor key{.actor = nullptr,
                              .alpha = alpha,
                              .textured = colour && colour->texture ? colour : nullptr,
                              .casts = casts_per_object.at(triangles.object[i])};
        auto group = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
            return g.surface.alpha == key.alpha && g.surface.textured == key.textured && g.surface.casts == key.casts;
        });
        if (group == groups.end()) group = groups.insert(groups.end(), {key, {}});
        group->chosen.push_back(i);
    }
    std::vector<CasterActor> out;
    for (Group& group : groups) {
        vtkSmartPointer<vtkPolyData> data = textured_polydata(triangles, group.chosen);
        vtkNew<vtkUnsignedCharArray> colours;
        colours->SetName("colour");
        colours->SetNumberOfComponents(3);
        for (std::size_t i : group.chosen) {
            const std::shared_ptr<const BaseColour>& colour =
                triangles.coloured() ? triangles.colour[i].colour : nullptr;
            const glm::dvec3 c = 255.0 * (group.surface.textured ? glm::dvec3(1.0)
                                          : colour               ? shown_factor(*colour)
                                                                 : colours_per_object.at(triangles.object[i]));
            colours->InsertNextTuple3(std::round(c.r), std::round(c.g), std::round(c.b));
        }
        data->GetCellData()->SetScalars(colours);
        vtkSmartPointer<vtkActor> actor = actor_of(data);
        auto* mapper = static_cast<vtkOpenGLPolyDataMapper*>(actor->GetMapper());
        mapper->SetScalarModeToUseCellFieldData();
        mapper->SelectColorArray("colour");
        mapper->SetColorModeToDirectScalars();
        mapper->ScalarVisibilityOn();
        group.surface.actor = actor;
        out.push_back(group.surface);
    }
    return out;
}

void pass_texture_coordinates(std::string& vertex, std::string& fragment) {
    vtkShaderProgram::Substitute(
        vertex, "//VTK::PositionVC::Dec",
        "//VTK::PositionVC::Dec\nin vec2 " + std::string(kUvAttribute) + ";\nout vec2 " + kUvAttribute + "VSOutput;\n",
        false);
    vtkShaderProgram::Substitute(
        vertex, "//VTK::PositionVC::Impl",
        "//VTK::PositionVC::Impl\n  " + std::string(kUvAttribute) + "VSOutput = " + kUvAttribute + ";\n", false);
    vtkShaderProgram::Substitute(fragment, "//VTK::Light::Dec",
                                 "//VTK::Light::Dec\nin vec2 " + std::string(kUvAttribute) + "VSOutput;\n", false);
}

vtkSmartPointer<vtkTextureObject> alpha_texture_object(const AlphaTest& test, vtkOpenGLRenderWindow* window) {
    auto texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(window);
    texture->SetInternalFormat(GL_R32F);
    texture->SetFormat(GL_RED);
    texture->SetDataType(GL_FLOAT);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->SetWrapS(vtkTextureObject::Repeat);
    texture->SetWrapT(vtkTextureObject::Repeat);
    static const float kOpaque = 1.0f;
    const bool made = test.texture ? texture->Create2DFromRaw(test.texture->width, test.texture->height, 1, VTK_FLOAT,
                                                              const_cast<float*>(test.texture->alpha.data()))
                                   : texture->Create2DFromRaw(1, 1, 1, VTK_FLOAT, const_cast<float*>(&kOpaque));
    if (!made) throw std::runtime_error("ShadowMapPass: an alpha-tested caster's texture could not be made");
    return texture;
}

}  // namespace shadowlab
