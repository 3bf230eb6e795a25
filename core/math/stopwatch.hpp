#pragma once
// Wall-clock milliseconds since construction, for the cost columns of measurements.
#include <chrono>

namespace shadowlab {

class Stopwatch {
public:
    double ms() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_ = Clock::now();
};

}  // namespace shadowlab
