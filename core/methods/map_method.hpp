#pragma once
// What a shadow-map method works with: a pure function of its inputs (camera, light, the boxes that
// matter for this view) and its settings that fills a ShadowSetup (maps, tiles, selection, named
// fallbacks) and, when a trace is asked for, records its steps. Registered in registry/registry.cpp.
#include "maps/map_lookup.hpp"
#include "maps/shadow_map.hpp"
#include "methods/settings.hpp"
#include "methods/shadow_inputs.hpp"
#include "trace/trace.hpp"
