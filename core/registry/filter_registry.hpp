#pragma once
// A filter from outside the shipped list (a test's throw-away filter, a plug-in): registered once,
// it is a choice of every map method's filter setting, its settings theirs, and the CPU lookup, the
// GPU pass, measure and the window read it like the shipped ones (lookup/shadow_filter.hpp).
#include "lookup/shadow_filter.hpp"

namespace shadowlab {

// Appends the filter (add_filter: throws std::invalid_argument for a name taken, a name that is not a
// GLSL name, or a missing function) and adds it and its settings to every map method.
void register_filter(FilterDescriptor filter);

}  // namespace shadowlab
