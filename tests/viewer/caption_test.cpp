// Text that fits: every text of every view of every method (captions, legends, the Error view's
// colour bar) lies within its panel, at a quarter of a 1280x800 window and at a small panel.
#include <gtest/gtest.h>
#include <vtkCoordinate.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include "registry/method.hpp"
#include "render/x_display.hpp"
#include "scene/scene_loader.hpp"
#include "views/view.hpp"

using namespace shadowlab;

namespace {

struct Overflow {
    std::string text;
    double left, right;
};

// Builds the view in a panel of the given size, renders it (the captions wrap as the render
// starts), and lists the texts whose bounding box leaves the panel's width.
std::vector<Overflow> overflowing_texts(const Inspection& in, const View& view, int width, int height) {
    const XDisplay x("caption test");
    vtkNew<vtkRenderWindow> window;
    window->SetInteractor(nullptr);
    window->SetDisplayId(x.handle());
    window->SetOffScreenRendering(1);
    window->SetStencilCapable(1);
    window->SetSize(width, height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    build_view(renderer, in, view, {.width = width, .height = height});
    window->Render();
    std::vector<Overflow> out;
    vtkPropCollection* props = renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp()) {
        auto* text = vtkTextActor::SafeDownCast(prop);
        if (!text) continue;
        double box[4];  // x min, x max, y min, y max in pixels from the text's anchor
        text->GetBoundingBox(renderer, box);
        const double anchor = text->GetPositionCoordinate()->GetComputedDisplayValue(renderer)[0];
        const double left = anchor + box[0], right = anchor + box[1];
        if (left < 0.0 || right > width) out.push_back({text->GetInput(), left, right});
    }
    window->Finalize();
    return out;
}

}  // namespace

class CaptionsFit : public ::testing::TestWithParam<std::string> {};

TEST_P(CaptionsFit, EveryTextOfEveryViewLiesWithinItsPanel) {
    const Scene scene = load_scene(std::string(SHADOWLAB_SOURCE_DIR) + "/data/scenes/box_on_plane.json");
    InspectionRequest request;
    request.method = GetParam();
    request.resolution = 256;
    request.image_width = 320;  // a technique's image: small, to keep the test fast
    request.image_height = 180;
    const Inspection in = inspect_scene(scene, request);
    for (const auto& [width, height] : {std::pair{620, 380}, std::pair{400, 300}})
        for (const View& view : all_views())
            for (const Overflow& o : overflowing_texts(in, view, width, height))
                ADD_FAILURE() << GetParam() << ", " << view.name << " view at " << width << "x" << height << ": '"
                              << o.text << "' spans x " << o.left << " to " << o.right;
}

INSTANTIATE_TEST_SUITE_P(AllMethods, CaptionsFit, ::testing::ValuesIn([] {
                             std::vector<std::string> names;
                             for (const Method& m : all_methods()) names.push_back(m.name);
                             return names;
                         }()));
