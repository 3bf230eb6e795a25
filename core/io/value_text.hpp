#pragma once
// A trace value as text, for people: numbers with 6 significant digits, vectors in brackets,
// matrices as four bracketed rows (row-major, as the column-vector matrix reads) on four lines.
#include <string>

#include "trace/trace.hpp"

namespace shadowlab {

std::string value_text(const TraceValue& value);

}  // namespace shadowlab
