#pragma once
// What a geometric technique works with: a pure function of the scene, its triangles, the camera
// image's visible points and its settings that yields a GeometryResult (verdicts per pixel, stencil
// polygons, counts, cost, named limits) and, when a trace is asked for, records its steps.
// Registered in registry/registry.cpp.
#include "methods/settings.hpp"
#include "reference/exact_shadows.hpp"
#include "scene/tessellation.hpp"
#include "techniques/geometry_result.hpp"
#include "trace/trace.hpp"
