#pragma once
// The textures a pass draws depth into and then reads texel by texel: a depth texture (nearest,
// clamped to its edges: texelFetch reads it) and the colour texture that keeps a framebuffer with
// it complete everywhere (unused otherwise). ShadowMapPass's maps and the camera's depth image for
// contact shadows (render/contact_depth_image.hpp) are drawn into these.
#include <vtkSmartPointer.h>

class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace shadowlab {

// `format`: vtkTextureObject's depth type (Fixed16, Fixed24, Float32).
vtkSmartPointer<vtkTextureObject> depth_texture(vtkOpenGLRenderWindow* window, int width, int height, int format);
vtkSmartPointer<vtkTextureObject> completing_colour_texture(vtkOpenGLRenderWindow* window, int width, int height);

}  // namespace shadowlab
