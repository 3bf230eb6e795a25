#include "raster/depth_format.hpp"

#include <cmath>

namespace shadowlab {

const char* to_string(DepthEncoding encoding) {
    switch (encoding) {
        case DepthEncoding::unorm16: return "unorm16";
        case DepthEncoding::unorm24: return "unorm24";
        case DepthEncoding::float32: return "float32";
    }
    return "?";
}

std::vector<DepthEncoding> depth_encodings() {
    return {DepthEncoding::float32, DepthEncoding::unorm24, DepthEncoding::unorm16};
}

std::vector<DepthFormat> depth_formats() {
    std::vector<DepthFormat> formats;
    for (DepthEncoding encoding : depth_encodings())
        for (bool reversed : {false, true}) formats.push_back({.encoding = encoding, .reversed = reversed});
    return formats;
}

std::string describe(const DepthFormat& format) {
    return std::string(to_string(format.encoding)) + (format.reversed ? " reversed" : "");
}

DepthCode depth_code(const DepthFormat& format, double stored) {
    const bool r = format.reversed;
    switch (format.encoding) {
        case DepthEncoding::unorm16:
            return r ? code_of<DepthEncoding::unorm16, true>(stored) : code_of<DepthEncoding::unorm16, false>(stored);
        case DepthEncoding::unorm24:
            return r ? code_of<DepthEncoding::unorm24, true>(stored) : code_of<DepthEncoding::unorm24, false>(stored);
        case DepthEncoding::float32:
            return r ? code_of<DepthEncoding::float32, true>(stored) : code_of<DepthEncoding::float32, false>(stored);
    }
    return 0;
}

double stored_depth(const DepthFormat& format, double depth) {
    return DepthDecoder(format)(depth_code(format, format_value(format, depth)));
}

double depth_step(const DepthFormat& format, double depth) {
    if (format.encoding != DepthEncoding::float32) return 1.0 / unorm_levels(format.encoding);
    // The float nearest s and its neighbour: above it, or below it at the top of the range.
    const float s = std::bit_cast<float>(depth_code(format, format_value(format, depth)));
    return s < 1.0f ? double(std::nextafter(s, 2.0f)) - s : double(s) - std::nextafter(s, 0.0f);
}

}  // namespace shadowlab
