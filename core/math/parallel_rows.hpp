#pragma once
// Image rows shared among the cores, interleaved: thread t takes rows t, t + n, t + 2n, ... Each
// row is independent, so the result does not depend on how many threads there were.
#include <algorithm>
#include <thread>
#include <vector>

namespace shadowlab {

// How many threads parallel_rows runs: `first` stays below it (per-thread accumulators).
inline int row_threads() { return int(std::max(1u, std::thread::hardware_concurrency())); }

// Calls rows(first, stride) once per thread.
template <class Rows>
void parallel_rows(Rows&& rows) {
    const int threads = row_threads();
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t) workers.emplace_back([&, t] { rows(t, threads); });
    for (std::thread& w : workers) w.join();
}

}  // namespace shadowlab
