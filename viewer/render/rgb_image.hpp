#pragma once
// An 8-bit RGB image, row 0 at the top, and its conversions to VTK images (row 0 at the bottom).
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkImageData;
class vtkRenderWindow;

namespace shadowlab {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;  // row-major, 3 bytes per pixel

    RgbImage() = default;
    RgbImage(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3) {}
    unsigned char* at(int x, int y) { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
    const unsigned char* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

vtkSmartPointer<vtkImageData> to_vtk_image(const RgbImage& image);
RgbImage from_vtk_image(vtkImageData* data);  // 3-component unsigned char data

// What a render window shows now (its back buffer).
RgbImage grab(vtkRenderWindow* window);

// The image as the bytes of a PNG file.
std::string png_bytes(const RgbImage& image);
// Throws std::runtime_error naming the file when it cannot be written.
void write_png(const RgbImage& image, const std::string& file);
// An 8-bit RGB PNG, as write_png writes them; throws std::runtime_error naming the file otherwise.
RgbImage read_png(const std::string& file);

}  // namespace shadowlab
