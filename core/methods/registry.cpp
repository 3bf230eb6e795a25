// The list of methods, in the order the UI shows them.
#include "methods/focused.hpp"
#include "methods/method.hpp"
#include "methods/uniform.hpp"

namespace shadowlab {

const std::vector<Method>& all_methods() {
    static const std::vector<Method> methods{
        {"uniform", "Uniform shadow map", "orthographic map fit to the whole scene's bounds", {}, compute_uniform},
        {"focused", "Focused shadow map", "orthographic map fit to the intersection body",
         {body_kernel_setting()}, compute_focused},
    };
    return methods;
}

const Method* find_method(const std::string& name) {
    for (const Method& m : all_methods())
        if (m.name == name) return &m;
    return nullptr;
}

}  // namespace shadowlab
