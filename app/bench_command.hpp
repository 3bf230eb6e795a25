#pragma once
// `shadowlab bench SCENE... [--methods a,b] [--resolutions 256,512,...] [--size WxH] --out DIR`:
// every method at every resolution on every scene; DIR/bench.csv, DIR/bench.png (error against
// cost, one line per method), DIR/bench_aliasing.png (max perspective m against cost) and
// DIR/bench_storage.png (storage efficiency against cost, a point per map method). With
// --filters: the filters' error against their cost instead (filter_bench.hpp). With --scheduler ADDR
// the runs are Dask tasks instead, on that scheduler (or `local`: a LocalCluster of two worker
// processes): the Python package's evaluate (python/shadowlab/corpus.py) writes DIR/bench.csv.
#include <string>
#include <vector>

#include "scene_source.hpp"

namespace shadowlab {

struct BenchOptions {
    std::vector<std::string> scene_files;
    SceneSource scene_source;          // which of each scene file's cameras and lights, or an engine's camera
    std::vector<std::string> methods;  // empty: all
    std::vector<int> resolutions{256, 512, 1024, 2048, 4096};
    int width = 640, height = 360;
    std::string out_dir;
    bool filters = false;   // each filter instead of each resolution (filter_bench.hpp)
    std::string scheduler;  // non-empty: the runs as Dask tasks on this scheduler's address, or `local`
};

void run_bench(const BenchOptions& options);

}  // namespace shadowlab
