#pragma once
// `shadowlab bench SCENE --filters [--methods a] [--resolutions N] [--size WxH] --out DIR`: each
// filter (hard, PCF box/tent/Poisson, PCSS, VSM with and without bleeding reduction, EVSM) at a few
// kernel sizes, for each method at the first resolution: DIR/bench_filters.csv and
// DIR/bench_filters.png, the visibility RMSE against the soft reference (for an area light) over
// the lookups' cost per frame, one line per filter family, labelled by kernel size: the Pareto front
// of error against cost.
#include "bench_command.hpp"

namespace shadowlab {

void run_filter_bench(const BenchOptions& options);

}  // namespace shadowlab
