#include "geometry/intersection_body.hpp"

namespace shadowlab {

const char* to_string(BodyKernel kernel) {
    switch (kernel) {
        case BodyKernel::float_clipper: return "float";
        case BodyKernel::epick: return "epick";
        case BodyKernel::epeck: return "epeck";
    }
    return "?";
}

std::optional<BodyKernel> body_kernel_from_string(const std::string& name) {
    for (BodyKernel k : {BodyKernel::float_clipper, BodyKernel::epick, BodyKernel::epeck})
        if (name == to_string(k)) return k;
    return std::nullopt;
}

IntersectionBody intersection_body(const BodyInput& input, BodyKernel kernel) {
    switch (kernel) {
        case BodyKernel::float_clipper: return intersection_body_float(input);
        case BodyKernel::epick: return intersection_body_cgal(input, /*exact=*/false);
        case BodyKernel::epeck: return intersection_body_cgal(input, /*exact=*/true);
    }
    return {};
}

}  // namespace shadowlab
