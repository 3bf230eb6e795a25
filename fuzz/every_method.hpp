#pragma once
// What both fuzzers do with a scene the loader accepted: every method of the registry on it, as
// `inspect` (traced) and `measure` (maps rasterized, every pixel judged) run them, with caps that keep
// one input well under a second under the sanitizers. A scene once accepted is the loader's promise
// that every method can compute it, so from there on any exception, crash, sanitizer report or
// non-finite map is a bug in core, not in the input: it aborts, and libFuzzer keeps the input.
#include <string>

#include "scene/scene.hpp"

namespace shadowlab::fuzzing {

[[noreturn]] void bug(const std::string& where, const std::string& what);

// Every method on the scene's first kMaxObjects objects.
void run_every_method(Scene scene);

}  // namespace shadowlab::fuzzing
