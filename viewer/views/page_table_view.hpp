#pragma once
// The Page table view's picture (page_table_view.cpp), without VTK: each clipmap level that holds a
// page the view marked or made resident, as its grid of pages_per_side² pages coloured by state
// (maps/page_table.hpp, PageState), in rows of small multiples; beside them the physical pool, the
// setup's texture in slots of page_size texels, each used slot in its page's level's colour.
#include <vector>
#include <glm/glm.hpp>

#include "maps/shadow_map.hpp"
#include "render/rgb_image.hpp"

namespace shadowlab {

// One level's grid in the picture, cut to the pages in use: every grid shows the same square of
// pages_shown² pages from first_page (all the levels' marked and resident pages within it, a
// margin around them; the whole grid when they spread over most of it). Page (x, y) of the level
// (v up, as the Shadow map view puts it) covers the cell_px² pixels from
// origin + (x - first.x, first.y + pages_shown - 1 - y) cell_px; where the square holds more pages
// per side than the picture gives it pixels, pages_per_pixel² pages share one pixel (the most
// telling state of them: over budget, needed, raised, empty).
struct PageGridPanel {
    int level = 0;
    glm::ivec2 origin{0};  // the grid's top-left pixel (rows from the top)
    int side_px = 0;       // the grid's width and height
    int cell_px = 1;
    int pages_per_pixel = 1;
    glm::ivec2 first_page{0};  // the square of pages shown
    int pages_shown = 0;
    glm::dvec3 colour{1.0};  // the level's colour: its frame, its label, its slots in the pool
};

// The pool: slot (i, j) (j up, as the texture's v) covers slot_px² pixels, one pixel of background
// between slots where they are 4 pixels or more.
struct PoolPanel {
    glm::ivec2 origin{0};  // top-left pixel
    int slots_per_side = 0;
    int slot_px = 0;
    int side_px = 0;
};

struct PagePicture {
    RgbImage image;
    std::vector<PageGridPanel> grids;  // the levels shown, finest first
    PoolPanel pool;
    int top_margin = 0, bottom_margin = 0;  // rows left to the legend and the caption
};

// The picture of a setup whose selection is Rule::pages; the pool holds texture_resolution / page_size
// slots per side. `kept`, per map (Inspection::pages_kept; empty: none): the resident pages a page
// cache kept from the view before, shown as cached.
PagePicture page_picture(const PageTable& table, const ShadowSetup& setup, int texture_resolution,
                         const std::vector<bool>& kept = {});

// The colours of the states, of a resident page kept from the view before (cached), and of the
// picture's background.
glm::dvec3 page_state_colour(PageState state);
extern const glm::dvec3 kCachedPage;
extern const glm::dvec3 kPageBackground;
// Whether the grid shows the page, and the pixel (x, y from the top) of the picture that does.
bool shows(const PageGridPanel& grid, const glm::ivec2& page);
glm::ivec2 page_pixel(const PageGridPanel& grid, const glm::ivec2& page);
// The centre pixel of pool slot (i, j).
glm::ivec2 slot_pixel(const PoolPanel& pool, const glm::ivec2& slot);
// The slot a map's viewport takes in a pool of slots_per_side slots.
glm::ivec2 slot_of(const ShadowMap& map, int slots_per_side);

}  // namespace shadowlab
