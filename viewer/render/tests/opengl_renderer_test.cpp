// Which OpenGL draws: a renderer string is found on the display the tests run on, and the software
// rasterizers (for which the window turns multisampling off) are told from hardware ones by name.
#include <gtest/gtest.h>

#include "render/opengl_renderer.hpp"

namespace shadowlab {
namespace {

TEST(OpenGLRenderer, TheDisplaysRendererIsNamed) {
    const std::string& renderer = opengl_renderer();
    EXPECT_FALSE(renderer.empty());
    EXPECT_EQ(&renderer, &opengl_renderer()) << "probed once";
}

TEST(OpenGLRenderer, SoftwareRasterizersAreToldFromGpus) {
    for (const char* software : {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Software Rasterizer (swrast)"})
        EXPECT_TRUE(is_software_renderer(software)) << software;
    for (const char* gpu : {"NVIDIA GeForce RTX 3060/PCIe/SSE2", "AMD Radeon RX 6600 (navi23, LLVM 15.0.6, DRM 3.49)",
                            "Mesa Intel(R) UHD Graphics 620 (KBL GT2)", ""})
        EXPECT_FALSE(is_software_renderer(gpu)) << gpu;
}

}  // namespace
}  // namespace shadowlab
