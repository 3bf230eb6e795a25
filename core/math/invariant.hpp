#pragma once
// assert_invariant(condition): a fact the code's reasoning rests on, stated where it holds, as
// Filament states `assert_invariant(f > n)`. Unlike `assert`, it stays on in every build, Release
// included, so the tests check it: a broken invariant throws InvariantBroken naming the condition
// and its place, and the window shows that line instead of drawing a wrong picture. Each check is a
// comparison or two, kept out of per-pixel and per-texel loops.
#include <stdexcept>
#include <string>

namespace shadowlab {

struct InvariantBroken : std::logic_error {
    using std::logic_error::logic_error;
};

[[noreturn]] inline void invariant_broken(const char* condition, const char* file, int line) {
    throw InvariantBroken(std::string(file) + ":" + std::to_string(line) + ": invariant broken: " + condition);
}

}  // namespace shadowlab

#define assert_invariant(condition) \
    ((condition) ? void(0) : ::shadowlab::invariant_broken(#condition, __FILE__, __LINE__))
