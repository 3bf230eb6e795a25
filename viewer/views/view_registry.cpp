// The list of views: one line each, the descriptor defined in the view's own file (declared in
// view_parts.hpp). Adding a view: see docs/ARCHITECTURE.md, "Adding a view".
#include <stdexcept>

#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

std::deque<View>& registry() {
    static std::deque<View> views{
        camera_view(), world_view(),   light_space_view(), ppls_view(),       shadow_map_view(), texels_view(),
        error_view(),  stencil_view(), page_table_view(),  difference_view(), flatland_view(),
    };
    return views;
}

}  // namespace

const std::deque<View>& all_views() { return registry(); }

const View* find_view(const std::string& name) {
    for (const View& v : registry())
        if (v.name == name) return &v;
    return nullptr;
}

std::string view_names(const std::string& separator) {
    std::string names;
    for (const View& v : registry()) names += (names.empty() ? "" : separator) + v.name;
    return names;
}

const View& view_or_throw(const std::string& name) {
    if (const View* v = find_view(name)) return *v;
    throw std::invalid_argument("unknown view '" + name + "' (known: " + view_names() + ")");
}

void register_view(View view) {
    if (find_view(view.name)) throw std::invalid_argument("view '" + view.name + "' is registered already");
    if (!view.build) throw std::invalid_argument("view '" + view.name + "': no build function");
    registry().push_back(std::move(view));
}

ViewReport build_view(vtkRenderer* renderer, const Inspection& in, const View& view, const ViewOptions& options) {
    if (!options.step.empty() && !in.trace.find(options.step))
        throw std::invalid_argument("method " + in.name() + " has no step '" + options.step + "'");
    return view.build(renderer, in, options);
}

void prepare_view(const Inspection& in, const View& view, const ViewOptions& options) {
    if (view.prepare) view.prepare(in, options);
}

}  // namespace shadowlab
