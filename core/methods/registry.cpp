// The list of methods, in the order the UI shows them.
#include "methods/focused.hpp"
#include "methods/lispsm.hpp"
#include "methods/method.hpp"
#include "methods/psm.hpp"
#include "methods/tsm.hpp"
#include "methods/uniform.hpp"
#include "methods/xpsm.hpp"

namespace shadowlab {

const std::vector<Method>& all_methods() {
    static const std::vector<Method> methods{
        {"uniform", "Uniform shadow map", "orthographic map fit to the whole scene's bounds", {}, compute_uniform},
        {"focused", "Focused shadow map", "orthographic map fit to the intersection body",
         {body_kernel_setting()}, compute_focused},
        {"psm", "Perspective shadow map", "Stamminger and Drettakis: the map built in the camera's post-perspective space",
         {body_kernel_setting()}, compute_psm},
        {"lispsm", "Light space perspective shadow map", "Wimmer et al.: a perspective warp along the view, in light space",
         {{"eta", "Lloyd's η: -1 uniform, 0 LiSPSM's n_opt, 1 PSM-like", "0", -1.0, 1.0, {}},
          {"n", "warp near distance; 0 = automatic (n_opt)", "0", 0.0, 1e12, {}},
          body_kernel_setting()},
         compute_lispsm},
        {"tsm", "Trapezoidal shadow map", "Martin and Tan: the view, seen from the light, bounded by a trapezoid warped onto the map",
         {{"focus", "80% rule: the focus region, this fraction of the view's depth, ends on the map's 80% line", "0.5",
           0.05, 1.0, {}},
          body_kernel_setting()},
         compute_tsm},
        {"xpsm", "Extended perspective shadow map", "Gusev's XPSM: a projection vector in light space, w clipped at εW",
         {{"coef", "warp strength: lengthP = coef / cos γ (1 / world units)", "0.05", 1e-6, 100.0, {}},
          {"epsilonW", "how close to w = 0 the warp may push a caster or receiver", "0.085", 1e-3, 0.999, {}},
          body_kernel_setting()},
         compute_xpsm},
    };
    return methods;
}

const Method* find_method(const std::string& name) {
    for (const Method& m : all_methods())
        if (m.name == name) return &m;
    return nullptr;
}

}  // namespace shadowlab
