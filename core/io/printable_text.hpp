#pragma once
// Text that is safe to print in one line of a message: valid UTF-8 kept as it is, every other byte
// (a binary file's bytes echoed by a parser, a control character, a line break) written as \xNN.
// A message quoting a file's content is then valid UTF-8 on any terminal or log.
#include <string>
#include <string_view>

namespace shadowlab {

std::string printable_text(std::string_view bytes);

}  // namespace shadowlab
