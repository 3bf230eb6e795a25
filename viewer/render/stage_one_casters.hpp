#pragma once
// What stage 1 of ShadowMapPass draws into a map when the scene's props will not do: the casters as
// triangles in the setup's coordinates (vertexMC is the point), split for a paraboloid as the CPU
// rasterizer splits them, or holding alpha-tested casters. The opaque triangles are one actor; each
// alpha test's triangles another, three vertices a triangle carrying its corners' texture coordinates
// (the vertex attribute shadowCasterUv), which stage 1 tests against the test's texture
// (glsl/caster_alpha.glsl) as the CPU rasterizer tests each texel. The Camera view's surfaces with a
// material are drawn alike (material_surfaces).
#include <memory>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

#include "scene/alpha_test.hpp"
#include "scene/base_colour.hpp"
#include "scene/tessellation.hpp"

class vtkActor;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace shadowlab {

struct CasterActor {
    vtkSmartPointer<vtkActor> actor;
    std::shared_ptr<const AlphaTest> alpha;  // null: opaque
    // A textured material's base colour, which stage 2 reads (render/base_colour_texture.hpp); null: the
    // actor's cell colours alone.
    std::shared_ptr<const BaseColour> textured = nullptr;
    bool casts = true;  // its triangles' objects cast (SceneObject::casts)
};

// The caster triangles (those whose object's flag is set) as actors: the opaque ones first (none when
// there are none), then one per alpha test, in the order of their first triangle.
std::vector<CasterActor> caster_actors(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object);

// Whether a triangle is drawn by material_surfaces rather than in its object's palette colour: it is
// alpha-tested or has a base colour.
bool has_material(const WorldTriangles& triangles, std::size_t triangle);

// The Camera view's surfaces with a material (has_material), every object's, one actor per alpha test,
// texture and casting flag, three vertices a triangle carrying its corners' texture coordinates. Each
// triangle's cells are coloured (the cell array "colour", as the views colour surfaces) white under a
// texture (stage 2 multiplies in the texture's colour), else its base colour factor as shown
// (shown_factor), else its object's colour. A map method's pass discards the alpha-tested ones'
// fragments where the test does not keep them, so that the camera sees through the holes its rays
// pass through in the reference.
std::vector<CasterActor> material_surfaces(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object,
                                           const std::vector<glm::dvec3>& colours_per_object);

// Vertex and fragment shader: the texture coordinates of a textured actor's vertices (the attribute
// shadowCasterUv) passed on to the fragment shader as shadowCasterUvVSOutput.
void pass_texture_coordinates(std::string& vertex, std::string& fragment);

// An alpha test's texture for the GPU: its alpha as one float channel (GL_R32F), nearest and repeated
// as AlphaTexture::at reads it; a test without a texture reads 1 everywhere.
vtkSmartPointer<vtkTextureObject> alpha_texture_object(const AlphaTest& test, vtkOpenGLRenderWindow* window);

}  // namespace shadowlab
