#pragma once
// Which of a scene file's cameras and lights the scene takes.
#include <cstddef>

namespace shadowlab {

// 0-based. A glTF file may hold several; a scene JSON and a lone mesh hold one of each (the default).
struct SceneChoice {
    std::size_t camera = 0;
    std::size_t light = 0;
};

}  // namespace shadowlab
