#pragma once
// Work run in a child process (fork), so that a crash, a hang or a runaway allocation inside a
// third-party reader cannot take the program down: the child's answer comes back as bytes through a
// pipe, and what went wrong with the child is said in one line. Assimp, which crashes on some files
// in its post-processing (README, "Opening your own models"), reads every mesh this way.
#include <cstddef>
#include <functional>
#include <string>

namespace shadowlab {

struct ChildLimits {
    double seconds = 60.0;  // wall-clock time before the child is killed
    // Resident memory the child may take beyond what it shares with the caller at the fork; watched
    // by the caller (an address-space limit would not do: AddressSanitizer reserves terabytes).
    std::size_t extra_bytes = std::size_t{4} << 30;  // a 1M-triangle OBJ takes under 1 GiB
};

struct ChildResult {
    std::string bytes;    // what the work returned, when it ended normally
    std::string failure;  // empty, or why there is no answer: "crashed (signal 11, SIGSEGV)",
                          // "took over 60 s", "took over 4 GiB of memory", "exited with status 3"
    bool ok() const { return failure.empty(); }
};

// Runs `work` in a forked child under `limits` and returns its bytes, or why there are none. An
// exception thrown by `work` is a failure too ("threw: what()"). The calling process only waits.
ChildResult run_in_child(const std::function<std::string()>& work, const ChildLimits& limits = {});

}  // namespace shadowlab
