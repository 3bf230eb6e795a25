#pragma once
// What stage 1 of ShadowMapPass draws into a map when the scene's props will not do: the casters as
// triangles in the setup's coordinates (vertexMC is the point), split for a paraboloid as the CPU
// rasterizer splits them, or holding alpha-tested casters. The opaque triangles are one actor; each
// alpha test's triangles another, three vertices a triangle carrying its corners' texture coordinates
// (the vertex attribute shadowCasterUv), which stage 1 tests against the test's texture
// (glsl/caster_alpha.glsl) as the CPU rasterizer tests each texel.
#include <memory>
#include <vector>
#include <vtkSmartPointer.h>

#include "scene/alpha_test.hpp"
#include "scene/tessellation.hpp"

class vtkActor;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace shadowlab {

struct CasterActor {
    vtkSmartPointer<vtkActor> actor;
    std::shared_ptr<const AlphaTest> alpha;  // null: opaque
};

// The caster triangles (those whose object's flag is set) as actors: the opaque ones first (none when
// there are none), then one per alpha test, in the order of their first triangle.
std::vector<CasterActor> caster_actors(const WorldTriangles& triangles, const std::vector<bool>& casts_per_object);

// Stage 2's alpha-tested surfaces (every object's, casting or not), one actor per alpha test, each
// triangle in its object's colour (the cell array "colour", as the views colour surfaces): the pass
// discards their fragments where the test does not keep them, so that the camera sees through the holes
// its rays pass through in the reference.
std::vector<CasterActor> alpha_tested_surfaces(const WorldTriangles& triangles,
                                               const std::vector<glm::dvec3>& colours_per_object);

// An alpha test's texture for the GPU: its alpha as one float channel (GL_R32F), nearest and repeated
// as AlphaTexture::at reads it; a test without a texture reads 1 everywhere.
vtkSmartPointer<vtkTextureObject> alpha_texture_object(const AlphaTest& test, vtkOpenGLRenderWindow* window);

}  // namespace shadowlab
