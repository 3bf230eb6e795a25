#include "lookup/shadow_filter.hpp"

namespace shadowlab {

int ShadowFilter::taps() const {
    switch (kind) {
        case FilterKind::hard: return 1;
        case FilterKind::pcf: return kernel_size * kernel_size;
        case FilterKind::pcss: return 2 * kernel_size * kernel_size;
        case FilterKind::vsm:
        case FilterKind::evsm: return 4;
    }
    return 1;
}

const char* to_string(FilterKind kind) {
    switch (kind) {
        case FilterKind::hard: return "hard";
        case FilterKind::pcf: return "pcf";
        case FilterKind::vsm: return "vsm";
        case FilterKind::evsm: return "evsm";
        case FilterKind::pcss: return "pcss";
    }
    return "?";
}

const char* to_string(PcfKernel kernel) {
    switch (kernel) {
        case PcfKernel::box: return "box";
        case PcfKernel::tent: return "tent";
        case PcfKernel::poisson: return "poisson";
    }
    return "?";
}

}  // namespace shadowlab
