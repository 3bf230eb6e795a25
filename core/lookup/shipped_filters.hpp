#pragma once
// The filters ShadowLab ships, one descriptor each (lookup/shadow_filter.hpp lists them).
#include "lookup/shadow_filter.hpp"

namespace shadowlab {

FilterDescriptor hard_filter();  // lookup/hard_filter.cpp
FilterDescriptor pcf_filter();   // lookup/pcf_filter.cpp
FilterDescriptor pcss_filter();  // lookup/pcss_filter.cpp
FilterDescriptor vsm_filter();   // lookup/variance_filters.cpp
FilterDescriptor evsm_filter();  // lookup/variance_filters.cpp
FilterDescriptor msm_filter();   // lookup/msm_filter.cpp
FilterDescriptor esm_filter();   // lookup/esm_filter.cpp

}  // namespace shadowlab
