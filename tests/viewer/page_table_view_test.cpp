// The Page table view (under Xvfb): a virtual map's levels as grids of pages coloured by state and
// its physical pool, each used slot in its page's level's colour; the caption's counts are the
// table's; over budget, the pages left without a slot show; any other method draws no page.
#include <algorithm>
#include <map>
#include <gtest/gtest.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include "render/x_display.hpp"
#include "view_test_support.hpp"
#include "metrics/page_caching.hpp"
#include "views/page_table_view.hpp"

using namespace shadowlab;
using namespace shadowlab::testing;

namespace {

constexpr int kWidth = 1280, kHeight = 720, kResolution = 2048;

Inspection inspect_virtual(const std::map<std::string, std::string>& settings = {}) {
    return inspect_scene(shipped_scene("default", kWidth, kHeight),
                         {.method = "virtual", .settings = settings, .resolution = kResolution});
}

// The view built in a window of the given size and rendered (the caption wraps as it starts), and its texts.
std::vector<std::string> texts_of(const Inspection& in) {
    const XDisplay x("page table test");
    vtkNew<vtkRenderWindow> window;
    window->SetInteractor(nullptr);
    window->SetDisplayId(x.handle());
    window->SetOffScreenRendering(1);
    window->SetSize(kWidth, kHeight);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    build_view(renderer, in, view_or_throw("pages"), {.width = kWidth, .height = kHeight});
    std::vector<std::string> texts;
    vtkPropCollection* props = renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp())
        if (auto* text = vtkTextActor::SafeDownCast(prop)) texts.push_back(text->GetInput());
    window->Finalize();
    return texts;
}

// The text holding `part`, its line breaks (the caption's wrapping) as spaces; empty when none does.
std::string text_with(const std::vector<std::string>& texts, const std::string& part) {
    for (std::string t : texts) {
        std::replace(t.begin(), t.end(), '\n', ' ');
        if (t.find(part) != std::string::npos) return t;
    }
    return {};
}

bool has_colour(const unsigned char* c, const glm::dvec3& colour, double tolerance = 3.0) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(c[i] - 255.0 * colour[i]) > tolerance) return false;
    return true;
}

size_t pixels_of(const RgbImage& image, const glm::dvec3& colour) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += has_colour(image.at(x, y), colour);
    return n;
}

int pages_in(const PageTable& table, PageState state) {
    int n = 0;
    for (int level = 0; level < static_cast<int>(table.levels.size()); ++level)
        for (int y = 0; y < table.pages_per_side; ++y)
            for (int x = 0; x < table.pages_per_side; ++x) n += page_state(table, {level, {x, y}}) == state;
    return n;
}

}  // namespace

// The table keeps the view's marks: the marked pages are the needed and the over-budget ones, the
// resident ones the needed and the raised ones.
TEST(PageTableView, TheStatesAccountForTheMarkedAndTheResidentPages) {
    for (const char* budget : {"4096", "24"}) {
        const Inspection in = inspect_virtual({{"page_budget", budget}});
        ASSERT_EQ(in.setup.selection.rule, MapSelection::Rule::pages) << budget;
        const PageTable& t = in.setup.selection.pages;
        ASSERT_GT(t.counts.marked, 0) << budget;
        EXPECT_EQ(pages_in(t, PageState::needed) + pages_in(t, PageState::over_budget), t.counts.marked) << budget;
        EXPECT_EQ(pages_in(t, PageState::needed) + pages_in(t, PageState::raised), int(t.pages.size())) << budget;
    }
}

// Every page of a shown level in its state's colour, every resident page's level shown, and every
// used slot of the pool in its page's level's colour.
TEST(PageTableView, ThePictureColoursEachPageByStateAndEachSlotByLevel) {
    const Inspection in = inspect_virtual();
    const PageTable& t = in.setup.selection.pages;
    ASSERT_FALSE(t.pages.empty());
    const PagePicture picture = page_picture(t, in.setup, in.resolution);
    ASSERT_FALSE(picture.grids.empty());
    EXPECT_EQ(picture.pool.slots_per_side, kResolution / t.page_size);
    size_t checked = 0;
    for (const PageGridPanel& g : picture.grids) {
        ASSERT_EQ(g.pages_per_pixel, 1) << "the default's pages in use fit at one page a pixel or more";
        for (int y = 0; y < t.pages_per_side; ++y)
            for (int x = 0; x < t.pages_per_side; ++x) {
                const PageState state = page_state(t, {g.level, {x, y}});
                if (!shows(g, {x, y})) {
                    ASSERT_EQ(state, PageState::empty) << "level " << g.level << " page " << x << "," << y << " hidden";
                    continue;
                }
                const glm::ivec2 p = page_pixel(g, {x, y});
                ASSERT_TRUE(has_colour(picture.image.at(p.x, p.y), page_state_colour(state)))
                    << "level " << g.level << " page " << x << "," << y;
                ++checked;
            }
    }
    EXPECT_GT(checked, 0u);
    for (size_t map = 0; map < t.pages.size(); ++map) {
        const auto g = std::find_if(picture.grids.begin(), picture.grids.end(),
                                    [&](const PageGridPanel& p) { return p.level == t.pages[map].level; });
        ASSERT_NE(g, picture.grids.end()) << "level " << t.pages[map].level << " holds a page and is not shown";
        const glm::ivec2 p = slot_pixel(picture.pool, slot_of(in.setup.maps[map], picture.pool.slots_per_side));
        EXPECT_TRUE(has_colour(picture.image.at(p.x, p.y), g->colour)) << "map " << map;
    }
}

// On screen: the resident pages' green and each shown level's colour (its frame and its slots).
TEST(PageTableView, TheViewDrawsTheGridsAndThePool) {
    const Inspection in = inspect_virtual();
    const PageTable& t = in.setup.selection.pages;
    const RgbImage image = render_view(in, view_or_throw("pages"), {}, kWidth, kHeight);
    EXPECT_GT(pixels_of(image, page_state_colour(PageState::needed)), 100u);
    const PagePicture picture = page_picture(t, in.setup, in.resolution);
    ASSERT_FALSE(picture.grids.empty());
    for (const PageGridPanel& g : picture.grids) EXPECT_GT(pixels_of(image, g.colour), 50u) << "level " << g.level;
}

// The caption's counts are the table's: resident, budget, marked; over budget, the bias added and
// the pages fewer; the legend counts each state's pages.
TEST(PageTableView, TheCaptionCountsAreTheTables) {
    for (const char* budget : {"4096", "24"}) {
        const Inspection in = inspect_virtual({{"page_budget", budget}});
        const PageTable& t = in.setup.selection.pages;
        const std::vector<std::string> texts = texts_of(in);
        const std::string caption = text_with(texts, "Page table — ");
        ASSERT_FALSE(caption.empty()) << budget;
        EXPECT_NE(caption.find(std::to_string(t.pages.size()) + " pages resident of a budget of " +
                               std::to_string(t.counts.budget) + " slots"),
                  std::string::npos)
            << caption;
        EXPECT_NE(caption.find(std::to_string(t.counts.marked) + " marked"), std::string::npos) << caption;
        EXPECT_EQ(caption.find("raised by") != std::string::npos, t.counts.bias_added > 0.0) << caption;
        if (t.counts.bias_added > 0.0) {
            EXPECT_NE(caption.find(std::to_string(t.counts.over_budget) + " fewer"), std::string::npos) << caption;
        }
        EXPECT_FALSE(
            text_with(texts, "needed and resident: " + std::to_string(pages_in(t, PageState::needed))).empty());
        EXPECT_FALSE(
            text_with(texts, "over budget (no slot): " + std::to_string(pages_in(t, PageState::over_budget))).empty());
    }
}

// A budget far below the marked pages: the bias is raised, and the pages left without a slot show red.
TEST(PageTableView, OverBudgetThePagesWithoutASlotShow) {
    const Inspection in = inspect_virtual({{"page_budget", "24"}});
    const PageTable& t = in.setup.selection.pages;
    ASSERT_GT(t.counts.marked, 24);
    EXPECT_GT(t.counts.bias_added, 0.0);
    EXPECT_LE(t.pages.size(), 24u);
    ASSERT_GT(pages_in(t, PageState::over_budget), 0);
    const RgbImage image = render_view(in, view_or_throw("pages"), {}, kWidth, kHeight);
    EXPECT_GT(pixels_of(image, page_state_colour(PageState::over_budget)), 20u);
}

// Another method: the caption says what the view shows, and no page is drawn.
TEST(PageTableView, AnotherMethodDrawsNoPages) {
    const Inspection in =
        inspect_scene(shipped_scene("default", kWidth, kHeight), {.method = "focused", .resolution = 1024});
    EXPECT_FALSE(text_with(texts_of(in), "virtual maps' pages only").empty());
    const RgbImage image = render_view(in, view_or_throw("pages"), {}, kWidth, kHeight);
    size_t drawn = 0;  // above the caption's rows: the background alone
    for (int y = 0; y < kHeight - 40; ++y)
        for (int x = 0; x < kWidth; ++x) drawn += !has_colour(image.at(x, y), kPageBackground);
    EXPECT_EQ(drawn, 0u);
}

// After the camera moves a little, most resident pages are the ones the view before held: shown as
// cached, each at its page's pixel, and counted in the caption; a page drawn anew stays white.
TEST(PageTableView, PagesKeptFromTheViewBeforeShowAsCached) {
    const Scene scene = shipped_scene("default", kWidth, kHeight);
    const InspectionRequest request{.method = "virtual", .resolution = kResolution};
    const Inspection before = inspect_scene(scene, request);
    Scene moved = scene;
    moved.camera.position.x += 0.5;
    moved.camera.target.x += 0.5;
    Inspection now = inspect_scene(moved, request);
    now.pages_kept = kept_maps(&before.setup, now.setup);
    const size_t kept = size_t(std::count(now.pages_kept.begin(), now.pages_kept.end(), true));
    ASSERT_GT(kept, now.setup.maps.size() / 2);
    ASSERT_LT(kept, now.setup.maps.size()) << "the move allocated no page: nothing would be drawn anew";
    const PageTable& table = now.setup.selection.pages;
    const PagePicture picture = page_picture(table, now.setup, kResolution, now.pages_kept);
    size_t cached_shown = 0, anew_shown = 0;
    for (const PageGridPanel& g : picture.grids) {
        ASSERT_EQ(g.pages_per_pixel, 1);
        for (size_t map = 0; map < table.pages.size(); ++map)
            if (table.pages[map].level == g.level && shows(g, table.pages[map].page)) {
                const glm::ivec2 p = page_pixel(g, table.pages[map].page);
                const bool cached = has_colour(picture.image.at(p.x, p.y), kCachedPage);
                EXPECT_EQ(cached, bool(now.pages_kept[map])) << "map " << map;
                (cached ? cached_shown : anew_shown) += 1;
            }
    }
    EXPECT_EQ(cached_shown, kept);
    EXPECT_EQ(cached_shown + anew_shown, table.pages.size());
    EXPECT_FALSE(text_with(texts_of(now), std::to_string(kept) + " of the resident pages kept").empty());
    EXPECT_FALSE(text_with(texts_of(before), "no pages cached").empty());
}
