#pragma once
// A file read whole, for the scene's readers.
#include <string>

namespace shadowlab {

// The file's bytes; SceneError "cannot open file" naming it when it is not a readable regular file.
std::string file_bytes(const std::string& file);

}  // namespace shadowlab
