// The list of filters: one line each. Adding a filter: its files, one line here (see
// docs/ARCHITECTURE.md, "Adding a filter"); a filter from outside the tree: register_filter.
#include "lookup/shadow_filter.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "lookup/shipped_filters.hpp"

namespace shadowlab {
namespace {

std::deque<FilterDescriptor>& filters() {
    static std::deque<FilterDescriptor> list{
        hard_filter(), pcf_filter(), vsm_filter(), evsm_filter(), msm_filter(), esm_filter(), pcss_filter(),
    };
    return list;
}

bool is_glsl_name(const std::string& name) {
    return !name.empty() && std::islower(static_cast<unsigned char>(name[0])) &&
           std::all_of(name.begin(), name.end(), [](char c) {
               return std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
                      c == '_';
           });
}

}  // namespace

bool ShadowFilter::reads_moments() const { return filter_of(*this).moments.of_depth != nullptr; }
bool ShadowFilter::soft() const { return filter_of(*this).soft; }
int ShadowFilter::taps() const { return filter_of(*this).texel_reads(*this); }

std::vector<KernelTap> filter_taps(const ShadowFilter& filter) { return filter_of(filter).taps(filter); }

const std::deque<FilterDescriptor>& all_filters() { return filters(); }

const FilterDescriptor* find_filter(const std::string& name) {
    for (const FilterDescriptor& f : filters())
        if (f.name == name) return &f;
    return nullptr;
}

const FilterDescriptor& filter_named(const std::string& name) {
    if (const FilterDescriptor* f = find_filter(name)) return *f;
    std::string known;
    for (const FilterDescriptor& f : filters()) known += (known.empty() ? "" : ", ") + f.name;
    throw std::invalid_argument("unknown filter '" + name + "' (known: " + known + ")");
}

const FilterDescriptor& filter_of(const ShadowFilter& filter) { return filter_named(filter.kind); }

int filter_index(const FilterDescriptor& descriptor) {
    const std::deque<FilterDescriptor>& list = filters();
    for (size_t i = 0; i < list.size(); ++i)
        if (&list[i] == &descriptor) return static_cast<int>(i);
    throw std::invalid_argument("filter '" + descriptor.name + "' is not registered");
}

void add_filter(FilterDescriptor descriptor) {
    const std::string& name = descriptor.name;
    if (!is_glsl_name(name))
        throw std::invalid_argument("filter '" + name + "': a name of lower-case letters, digits and '_'");
    if (find_filter(name)) throw std::invalid_argument("filter '" + name + "' is registered already");
    if (!descriptor.taps || !descriptor.texel_reads || !descriptor.visibility)
        throw std::invalid_argument("filter '" + name + "': set taps, texel_reads and visibility");
    if (descriptor.moments.of_depth && !descriptor.moments.depth_statistics)
        throw std::invalid_argument("filter '" + name + "': moments need their depth_statistics");
    filters().push_back(std::move(descriptor));
}

}  // namespace shadowlab
