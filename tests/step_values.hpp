#pragma once
// The numbers a traced step recorded, for the tests that read a method's choices back.
#include <stdexcept>
#include <string>
#include <variant>

#include "trace/trace.hpp"

namespace shadowlab::testing {

// The number `name` of step `step`; throws naming what is missing.
inline double step_value(const Trace& trace, const std::string& step, const std::string& name) {
    const Step* s = trace.find(step);
    if (!s) throw std::runtime_error("no step " + step);
    for (const NamedValue& v : s->values)
        if (v.name == name) return std::get<double>(v.value);
    throw std::runtime_error("no value " + name + " in step " + step);
}

}  // namespace shadowlab::testing
