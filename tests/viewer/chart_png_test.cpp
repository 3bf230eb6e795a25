// write_chart_png renders for real (run under xvfb-run): the PNG is read back with vtkPNGReader.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <stdexcept>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include "plot/chart_png.hpp"

using namespace shadowlab;

namespace {

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<unsigned char> pixels;
};

Image read_chart(const std::string& file) {
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkImageData* data = reader->GetOutput();
    int dims[3];
    data->GetDimensions(dims);
    Image image{dims[0], dims[1], data->GetNumberOfScalarComponents(), {}};
    const auto* p = static_cast<const unsigned char*>(data->GetScalarPointer());
    if (p) image.pixels.assign(p, p + size_t(image.width) * image.height * image.channels);
    return image;
}

size_t distinct_colors(const Image& image) {
    std::set<uint32_t> colors;
    for (size_t i = 0; i + 2 < image.pixels.size(); i += image.channels)
        colors.insert(image.pixels[i] << 16 | image.pixels[i + 1] << 8 | image.pixels[i + 2]);
    return colors.size();
}

size_t pixels_near(const Image& image, const std::array<unsigned char, 3>& rgb, int tolerance = 20) {
    size_t count = 0;
    for (size_t i = 0; i + 2 < image.pixels.size(); i += image.channels)
        if (std::abs(image.pixels[i] - rgb[0]) <= tolerance && std::abs(image.pixels[i + 1] - rgb[1]) <= tolerance &&
            std::abs(image.pixels[i + 2] - rgb[2]) <= tolerance)
            ++count;
    return count;
}

std::string temp_png(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("shadowlab_" + name + ".png")).string();
}

ChartSpec two_series() {
    ChartSpec chart{"Misclassified pixels", "map resolution", "share", false, false, 800, 500, {}};
    ChartSeries warped{"lispsm", {}, {}, {}, true, {}, {200, 30, 30}};
    ChartSeries uniform{"uniform", {}, {}, {}, false, {}, {}};  // palette colour
    for (int i = 0; i < 8; ++i) {
        const double n = 256 << i;
        warped.x.push_back(n);
        warped.y.push_back(0.2 / (i + 1));
        warped.labels.push_back(i == 3 ? "fallback" : "");
        warped.marked.push_back(i == 3);
        uniform.x.push_back(n);
        uniform.y.push_back(0.3 / (0.5 * i + 1));
    }
    chart.series = {warped, uniform};
    return chart;
}

}  // namespace

TEST(ChartPng, TwoSeriesDrawnInTheirColours) {
    const ChartSpec chart = two_series();
    const std::string file = temp_png("chart_two_series");
    write_chart_png(chart, file);

    const Image image = read_chart(file);
    EXPECT_EQ(image.width, 800);
    EXPECT_EQ(image.height, 500);
    EXPECT_GT(distinct_colors(image), 10u);
    for (size_t i = 0; i < chart.series.size(); ++i)
        EXPECT_GT(pixels_near(image, series_color(chart, i)), 50u) << chart.series[i].name;
    std::filesystem::remove(file);
}

TEST(ChartPng, PaletteColourWhenNoneIsGiven) {
    const ChartSpec chart = two_series();
    EXPECT_EQ(series_color(chart, 0), (std::array<unsigned char, 3>{200, 30, 30}));
    EXPECT_NE(series_color(chart, 1), (std::array<unsigned char, 3>{0, 0, 0}));
}

TEST(ChartPng, LogAxesDropNonPositivePoints) {
    ChartSpec chart = two_series();
    chart.log_x = chart.log_y = true;
    chart.series[0].y[2] = 0.0;
    chart.series[1].x[0] = -1.0;
    const std::string file = temp_png("chart_log");
    ASSERT_NO_THROW(write_chart_png(chart, file));
    const Image image = read_chart(file);
    EXPECT_EQ(image.width, 800);
    EXPECT_GT(distinct_colors(image), 10u);
    std::filesystem::remove(file);
}

TEST(ChartPng, MalformedSeriesThrows) {
    ChartSpec chart = two_series();
    chart.series[1].y.pop_back();
    EXPECT_THROW(write_chart_png(chart, temp_png("chart_malformed")), std::runtime_error);
}

TEST(ChartPng, UnwritableFileThrows) {
    EXPECT_THROW(write_chart_png(two_series(), "/nonexistent-directory/chart.png"), std::runtime_error);
}

TEST(ChartPng, NoDisplayThrowsAClearMessage) {
    const char* display = std::getenv("DISPLAY");
    const std::string saved = display ? display : "";
    setenv("DISPLAY", ":4999", 1);  // no server there
    try {
        write_chart_png(two_series(), temp_png("chart_no_display"));
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("xvfb-run"), std::string::npos) << e.what();
    }
    if (display)
        setenv("DISPLAY", saved.c_str(), 1);
    else
        unsetenv("DISPLAY");
}
