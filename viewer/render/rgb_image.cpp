#include "render/rgb_image.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

namespace shadowlab {

vtkSmartPointer<vtkImageData> to_vtk_image(const RgbImage& image) {
    auto data = vtkSmartPointer<vtkImageData>::New();
    data->SetDimensions(image.width, image.height, 1);
    vtkNew<vtkUnsignedCharArray> pixels;
    pixels->SetNumberOfComponents(3);
    pixels->SetNumberOfTuples(static_cast<vtkIdType>(image.width) * image.height);
    const size_t row = static_cast<size_t>(image.width) * 3;
    for (int y = 0; y < image.height; ++y)
        std::copy_n(image.at(0, image.height - 1 - y), row, pixels->GetPointer(static_cast<vtkIdType>(y * row)));
    data->GetPointData()->SetScalars(pixels);
    return data;
}

RgbImage from_vtk_image(vtkImageData* data) {
    const int* dims = data->GetDimensions();
    RgbImage image(dims[0], dims[1]);
    const auto* pixels = static_cast<const unsigned char*>(data->GetScalarPointer());
    const size_t row = static_cast<size_t>(dims[0]) * 3;
    for (int y = 0; y < dims[1]; ++y) std::copy_n(pixels + (dims[1] - 1 - y) * row, row, image.at(0, y));
    return image;
}

std::string png_bytes(const RgbImage& image) {
    vtkNew<vtkPNGWriter> writer;
    writer->WriteToMemoryOn();
    writer->SetInputData(to_vtk_image(image));
    writer->Write();
    vtkUnsignedCharArray* bytes = writer->GetResult();
    if (writer->GetErrorCode() != 0 || !bytes) throw std::runtime_error("cannot encode a PNG");
    const auto* first = bytes->GetPointer(0);
    return std::string(first, first + bytes->GetNumberOfValues());
}

void write_png(const RgbImage& image, const std::string& file) {
    const std::string bytes = png_bytes(image);
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + file);
}

RgbImage read_png(const std::string& file) {
    vtkNew<vtkPNGReader> reader;
    if (!reader->CanReadFile(file.c_str())) throw std::runtime_error("cannot read " + file + " as a PNG");
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkImageData* data = reader->GetOutput();
    if (data->GetNumberOfScalarComponents() != 3 || data->GetScalarType() != VTK_UNSIGNED_CHAR)
        throw std::runtime_error(file + ": not an 8-bit RGB PNG");
    return from_vtk_image(data);
}

RgbImage grab(vtkRenderWindow* window) {
    vtkNew<vtkWindowToImageFilter> filter;
    filter->SetInput(window);
    filter->SetInputBufferTypeToRGB();
    filter->ReadFrontBufferOff();
    filter->Update();
    return from_vtk_image(filter->GetOutput());
}

}  // namespace shadowlab
