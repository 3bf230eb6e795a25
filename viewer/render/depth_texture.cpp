#include "render/depth_texture.hpp"

#include <vtkOpenGLRenderWindow.h>
#include <vtkTextureObject.h>

namespace shadowlab {

vtkSmartPointer<vtkTextureObject> depth_texture(vtkOpenGLRenderWindow* window, int width, int height, int format) {
    auto depth = vtkSmartPointer<vtkTextureObject>::New();
    depth->SetContext(window);
    depth->SetMinificationFilter(vtkTextureObject::Nearest);
    depth->SetMagnificationFilter(vtkTextureObject::Nearest);
    depth->SetWrapS(vtkTextureObject::ClampToEdge);
    depth->SetWrapT(vtkTextureObject::ClampToEdge);
    depth->AllocateDepth(width, height, format);
    return depth;
}

vtkSmartPointer<vtkTextureObject> completing_colour_texture(vtkOpenGLRenderWindow* window, int width, int height) {
    auto colour = vtkSmartPointer<vtkTextureObject>::New();
    colour->SetContext(window);
    colour->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
    return colour;
}

}  // namespace shadowlab
