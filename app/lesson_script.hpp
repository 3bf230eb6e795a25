#pragma once
// The interactive lesson page's script: web/src/lesson.js with three.js, bundled by esbuild at build
// time (web/bundle.sh), to be inlined into the page's <script> element.
#include <string_view>

namespace shadowlab {

std::string_view lesson_script();

}  // namespace shadowlab
