// The Page table view: a virtual shadow map's pages (maps/page_table.hpp). Each clipmap level that
// holds a marked or resident page, as its grid of pages coloured by state, in rows of small
// multiples, and the physical pool beside them, each used slot in its page's level's colour; a
// legend of the states (with their pages) and the levels, and a caption with the allocation's
// counts. One frame only: pages cached from a previous frame are not told apart. For any other
// method it says so in its caption and draws nothing.
#include "views/page_table_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include <vtkRenderer.h>

#include "views/space_parts.hpp"
#include "views/view_parts.hpp"

namespace shadowlab {

const glm::dvec3 kPageBackground{0.10, 0.10, 0.12};
const glm::dvec3 kCachedPage{0.78, 0.70, 0.52};  // khaki: apart from the levels' saturated hues

// The states apart from the levels' hues: in use bright, held at the raised bias grey, wanting red.
glm::dvec3 page_state_colour(PageState state) {
    switch (state) {
        case PageState::needed: return {0.93, 0.93, 0.93};       // marked and resident
        case PageState::raised: return {0.55, 0.56, 0.62};       // resident at the raised bias
        case PageState::over_budget: return {0.96, 0.22, 0.20};  // marked, no slot
        case PageState::empty: break;
    }
    return {0.24, 0.24, 0.28};
}

bool shows(const PageGridPanel& g, const glm::ivec2& page) {
    return glm::all(glm::greaterThanEqual(page, g.first_page)) &&
           glm::all(glm::lessThan(page, g.first_page + g.pages_shown));
}

glm::ivec2 page_pixel(const PageGridPanel& g, const glm::ivec2& page) {
    const glm::ivec2 cell = (page - g.first_page) / g.pages_per_pixel;
    const int rows = (g.pages_shown + g.pages_per_pixel - 1) / g.pages_per_pixel;
    return g.origin + glm::ivec2(cell.x, rows - 1 - cell.y) * g.cell_px + g.cell_px / 2;
}

glm::ivec2 slot_pixel(const PoolPanel& pool, const glm::ivec2& slot) {
    return pool.origin + glm::ivec2(slot.x, pool.slots_per_side - 1 - slot.y) * pool.slot_px + pool.slot_px / 2;
}

glm::ivec2 slot_of(const ShadowMap& map, int slots_per_side) {
    return {static_cast<int>(std::floor(map.viewport.x * slots_per_side + 0.5)),
            static_cast<int>(std::floor(map.viewport.y * slots_per_side + 0.5))};
}

namespace {

using Rgb8 = std::array<unsigned char, 3>;
Rgb8 bytes(const glm::dvec3& c) {
    return {static_cast<unsigned char>(std::lround(255.0 * std::clamp(c.r, 0.0, 1.0))),
            static_cast<unsigned char>(std::lround(255.0 * std::clamp(c.g, 0.0, 1.0))),
            static_cast<unsigned char>(std::lround(255.0 * std::clamp(c.b, 0.0, 1.0)))};
}

void fill(RgbImage& image, glm::ivec2 from, glm::ivec2 size, const glm::dvec3& colour) {
    const Rgb8 c = bytes(colour);
    for (int y = std::max(0, from.y); y < std::min(image.height, from.y + size.y); ++y)
        for (int x = std::max(0, from.x); x < std::min(image.width, from.x + size.x); ++x)
            std::copy(c.begin(), c.end(), image.at(x, y));
}

// A frame `width` pixels wide just outside the square at `from`.
void frame(RgbImage& image, glm::ivec2 from, int side, int width, const glm::dvec3& colour) {
    fill(image, from - width, {side + 2 * width, width}, colour);
    fill(image, {from.x - width, from.y + side}, {side + 2 * width, width}, colour);
    fill(image, {from.x - width, from.y}, {width, side}, colour);
    fill(image, {from.x + side, from.y}, {width, side}, colour);
}

// The levels' colours: evenly around the hue circle (short of closing it), bright enough on the background.
glm::dvec3 hue(double h) {
    const glm::dvec3 k = glm::mod(glm::dvec3(5.0, 3.0, 1.0) + h * 6.0, 6.0);
    const glm::dvec3 rgb = 1.0 - glm::clamp(glm::min(k, 4.0 - k), 0.0, 1.0);  // hsv with s = 1, v = 1
    return 0.95 * (0.35 + 0.65 * rgb);  // a touch of white: light on the dark background
}
glm::dvec3 level_colour(size_t rank, size_t count) {
    return hue(0.85 * double(rank) / double(std::max<size_t>(1, count)));
}

// How a pixel covering several pages reads: the most telling state; a resident page kept from the
// view before (cached) tells less than one drawn anew.
constexpr int kCachedTelling = 2;
int telling(PageState s, bool kept) {
    switch (s) {
        case PageState::over_budget: return 4;
        case PageState::needed: return kept ? kCachedTelling : 3;
        case PageState::raised: return kept ? kCachedTelling : 1;
        case PageState::empty: break;
    }
    return 0;
}
glm::dvec3 telling_colour(int telling) {
    constexpr PageState kByTelling[5] = {PageState::empty, PageState::raised, PageState::needed, PageState::needed,
                                         PageState::over_budget};
    return telling == kCachedTelling ? kCachedPage : page_state_colour(kByTelling[telling]);
}

std::vector<int> shown_levels(const PageTable& table) {
    std::vector<int> levels;
    const int n = table.pages_per_side;
    for (int level = 0; level < static_cast<int>(table.levels.size()); ++level) {
        bool any = false;
        for (int y = 0; y < n && !any; ++y)
            for (int x = 0; x < n && !any; ++x) any = page_state(table, {level, {x, y}}) != PageState::empty;
        if (any) levels.push_back(level);
    }
    return levels;
}

// Rows and columns of grids, the pool (a square as tall as the rows) beside them: the arrangement
// whose picture is closest to 16:9.
glm::ivec2 arrangement(int grids) {
    glm::ivec2 best{1, std::max(1, grids)};
    double best_miss = 1e300;
    for (int rows = 1; rows <= std::max(1, grids); ++rows) {
        const int columns = (std::max(1, grids) + rows - 1) / rows;
        const double miss = std::abs(std::log(double(columns + rows) / rows / (16.0 / 9.0)));
        if (miss < best_miss) best_miss = miss, best = {rows, columns};
    }
    return best;
}

}  // namespace

// The square of pages every grid shows: the levels' pages in use within it, and a margin.
std::pair<glm::ivec2, int> shown_square(const PageTable& table, const std::vector<int>& levels) {
    const int n = std::max(1, table.pages_per_side);
    glm::ivec2 lo(n), hi(-1);
    for (int level : levels)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                if (page_state(table, {level, {x, y}}) != PageState::empty)
                    lo = glm::min(lo, glm::ivec2(x, y)), hi = glm::max(hi, glm::ivec2(x, y));
    if (hi.x < 0) return {glm::ivec2(0), n};
    constexpr int kMargin = 2, kLeast = 12;
    int side = std::max(hi.x - lo.x, hi.y - lo.y) + 1 + 2 * kMargin;
    side = std::min(n, std::max(side, kLeast));
    if (side > n * 2 / 3) return {glm::ivec2(0), n};  // most of the grid: all of it
    const glm::ivec2 first = glm::clamp((lo + hi + 1) / 2 - side / 2, glm::ivec2(0), glm::ivec2(n - side));
    return {first, side};
}

PagePicture page_picture(const PageTable& table, const ShadowSetup& setup, int texture_resolution,
                         const std::vector<bool>& kept) {
    constexpr int kGridPixels = 160;  // a grid's side at most, in pixels: about 1:1 in a 1280x720 view
    const std::vector<int> levels = shown_levels(table);
    const auto [first, w] = shown_square(table, levels);
    const int per_pixel = (w + kGridPixels - 1) / kGridPixels;
    const int cell = std::max(1, kGridPixels / w);
    const int cells = (w + per_pixel - 1) / per_pixel;
    const int grid = cells * cell;
    const int gap = std::max(24, grid / 4);  // room for a grid's label above it
    const glm::ivec2 rc = arrangement(static_cast<int>(levels.size()));
    PagePicture out;
    out.top_margin = std::max(40, grid * 3 / 10);
    out.bottom_margin = std::max(48, grid * 4 / 10);
    const int left = gap / 2;
    const int rows_height = rc.x * (grid + gap);
    const int slots = table.page_size > 0 ? std::max(1, texture_resolution / table.page_size) : 1;
    PoolPanel& pool = out.pool;
    pool.slots_per_side = slots;
    pool.slot_px = std::max(1, (rows_height - gap) / slots);
    pool.side_px = pool.slot_px * slots;
    pool.origin = {left + rc.y * (grid + gap) + gap, out.top_margin + gap};
    out.image = RgbImage(pool.origin.x + pool.side_px + left, out.top_margin + rows_height + out.bottom_margin);
    fill(out.image, {0, 0}, {out.image.width, out.image.height}, kPageBackground);

    for (size_t k = 0; k < levels.size(); ++k) {
        const int row = static_cast<int>(k) / rc.y, column = static_cast<int>(k) % rc.y;
        PageGridPanel g{.level = levels[k],
                        .origin = {left + column * (grid + gap), out.top_margin + row * (grid + gap) + gap},
                        .side_px = grid,
                        .cell_px = cell,
                        .pages_per_pixel = per_pixel,
                        .first_page = first,
                        .pages_shown = w,
                        .colour = level_colour(k, levels.size())};
        std::vector<int> shown(std::size_t(cells) * cells, 0);  // the most telling state per cell
        for (int y = 0; y < w; ++y)
            for (int x = 0; x < w; ++x) {
                const PageAddress a{g.level, first + glm::ivec2(x, y)};
                const int map = table.map_of(a);
                const int s = telling(page_state(table, a), map >= 0 && std::size_t(map) < kept.size() && kept[map]);
                int& at = shown[std::size_t(y / per_pixel) * cells + x / per_pixel];
                at = std::max(at, s);
            }
        const int cell_gap = cell >= 12 ? 2 : cell >= 4 ? 1 : 0;  // pages apart where they are large enough to tell
        fill(out.image, g.origin, {grid, grid}, kPageBackground);
        for (int cy = 0; cy < cells; ++cy)
            for (int cx = 0; cx < cells; ++cx)
                fill(out.image, g.origin + glm::ivec2(cx, cells - 1 - cy) * cell, {cell - cell_gap, cell - cell_gap},
                     telling_colour(shown[std::size_t(cy) * cells + cx]));
        frame(out.image, g.origin, grid, 2, g.colour);
        out.grids.push_back(g);
    }

    const int slot_gap = pool.slot_px >= 4 ? 1 : 0;
    fill(out.image, pool.origin, {pool.side_px, pool.side_px}, kPageBackground);
    for (int j = 0; j < slots; ++j)
        for (int i = 0; i < slots; ++i)
            fill(out.image, pool.origin + glm::ivec2(i, slots - 1 - j) * pool.slot_px,
                 {pool.slot_px - slot_gap, pool.slot_px - slot_gap}, page_state_colour(PageState::empty));
    for (size_t map = 0; map < setup.maps.size() && map < table.pages.size(); ++map) {
        const glm::ivec2 slot = slot_of(setup.maps[map], slots);
        const auto g = std::find_if(out.grids.begin(), out.grids.end(),
                                    [&](const PageGridPanel& p) { return p.level == table.pages[map].level; });
        if (g == out.grids.end() || slot.x < 0 || slot.y < 0 || slot.x >= slots || slot.y >= slots) continue;
        fill(out.image, pool.origin + glm::ivec2(slot.x, slots - 1 - slot.y) * pool.slot_px,
             {pool.slot_px - slot_gap, pool.slot_px - slot_gap}, g->colour);
    }
    frame(out.image, pool.origin, pool.side_px, 2, glm::dvec3(0.85));
    return out;
}

namespace {

std::string counted(int n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string levels_text(double levels) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", levels);
    return text;
}

// A point of the picture (x, y from the top) where add_world_label pins text: show_image puts pixel
// (x, y) at the world point (x, height - 1 - y).
glm::dvec3 at_pixel(const RgbImage& image, glm::ivec2 p) { return {p.x, image.height - 1 - p.y, 0.5}; }

ViewReport build_page_table_view(vtkRenderer* renderer, const Inspection& in, const ViewOptions&) {
    renderer->SetBackground(kPageBackground.r, kPageBackground.g, kPageBackground.b);
    if (!in.has_map() || in.setup.selection.rule != MapSelection::Rule::pages) {
        const std::string why =
            !in.has_map() ? "a geometric technique, no map"
                          : "its maps are chosen by " + std::string(to_string(in.setup.selection.rule)) + ", not paged";
        add_caption(renderer, "Page table — " + in.name() + ": this view shows virtual maps' pages only (" + why + ")");
        return {};
    }
    const PageTable& table = in.setup.selection.pages;
    const PagePicture picture = page_picture(table, in.setup, in.resolution, in.pages_kept);
    const int cached = static_cast<int>(std::count(in.pages_kept.begin(), in.pages_kept.end(), true));
    show_image(renderer, picture.image);

    int states[4] = {0, 0, 0, 0};
    std::vector<int> resident_per_level(table.levels.size(), 0), over_per_level(table.levels.size(), 0);
    for (int level = 0; level < static_cast<int>(table.levels.size()); ++level)
        for (int y = 0; y < table.pages_per_side; ++y)
            for (int x = 0; x < table.pages_per_side; ++x) {
                const PageState s = page_state(table, {level, {x, y}});
                ++states[static_cast<int>(s)];
                if (s == PageState::needed || s == PageState::raised) ++resident_per_level[level];
                if (s == PageState::over_budget) ++over_per_level[level];
            }
    std::vector<LegendEntry> legend{
        {page_state_colour(PageState::needed),
         "needed and resident: " + std::to_string(states[int(PageState::needed)]) +
             (in.pages_kept.empty() ? "" : " (drawn anew when not cached)")},
        {kCachedPage, "resident, cached from the view before: " + std::to_string(cached)},
        {page_state_colour(PageState::raised),
         "resident, needed once the bias was raised: " + std::to_string(states[int(PageState::raised)])},
        {page_state_colour(PageState::over_budget),
         "needed, over budget (no slot): " + std::to_string(states[int(PageState::over_budget)])},
        {page_state_colour(PageState::empty), "empty"}};
    for (const PageGridPanel& g : picture.grids) {
        legend.push_back(
            {g.colour, (&g == &picture.grids.front() ? "slots of level " : "level ") + std::to_string(g.level)});
        std::string text =
            "level " + std::to_string(g.level) + "\n" + std::to_string(resident_per_level[g.level]) + " resident";
        if (over_per_level[g.level] > 0) text += ", " + std::to_string(over_per_level[g.level]) + " over";
        add_world_label(renderer, at_pixel(picture.image, g.origin), text, 12, g.colour, {0, 4});
    }
    add_legend(renderer, legend);
    const PoolPanel& pool = picture.pool;
    add_world_label(renderer, at_pixel(picture.image, pool.origin),
                    "physical pool\n" + std::to_string(pool.slots_per_side) + "×" +
                        std::to_string(pool.slots_per_side) + " slots of " + std::to_string(table.page_size) + "²",
                    12, glm::dvec3(0.85), {0, 4});

    const PageCounts& c = table.counts;
    std::string caption = "Page table — " + in.name() + ": " + counted(int(table.pages.size()), "page", "pages") +
                          " resident of a budget of " + std::to_string(c.budget) + " slots (" +
                          std::to_string(in.resolution) + "² pool), " + std::to_string(c.marked) + " marked";
    if (c.bias_added > 0.0)
        caption += "; resolution bias raised by " + levels_text(c.bias_added) + " level(s) to fit, " +
                   std::to_string(c.over_budget) + " fewer";
    if (c.dropped > 0) caption += ", " + std::to_string(c.dropped) + " left without a slot";
    const int n = table.pages_per_side;
    std::string grids = ".\nGrids: " + std::to_string(picture.grids.size()) + " of " +
                        std::to_string(table.levels.size()) + " levels of " + std::to_string(n) + "×" +
                        std::to_string(n) + " pages (v up)";
    if (!picture.grids.empty()) {
        const PageGridPanel& g = picture.grids.front();
        if (g.pages_shown < n)
            grids += ", each cut to pages " + std::to_string(g.first_page.x) + "–" +
                     std::to_string(g.first_page.x + g.pages_shown - 1) + " × " + std::to_string(g.first_page.y) + "–" +
                     std::to_string(g.first_page.y + g.pages_shown - 1) + ", which hold every page in use";
        if (g.pages_per_pixel > 1) grids += ", " + std::to_string(g.pages_per_pixel) + "² pages a pixel";
    }
    caption += grids + "; pool slots in their page's level's colour. " +
               (in.pages_kept.empty() ? std::string("One frame: no pages cached from a previous one.")
                                      : std::to_string(cached) +
                                            " of the resident pages kept from the view before (a "
                                            "page cache draws only the other " +
                                            std::to_string(int(table.pages.size()) - cached) + ").");
    add_caption(renderer, caption);
    return {};
}

}  // namespace

View page_table_view() {
    return {.name = "pages",
            .title = "Page table",
            .prepare = {},  // reads the setup only
            .build = build_page_table_view,
            .choosers = {},
            .interaction = {.drag = ViewDrag::pans_image}};
}

}  // namespace shadowlab
