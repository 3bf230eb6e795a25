#include "io/value_text.hpp"

#include <cstdio>

#include "math/matrix.hpp"

namespace shadowlab {
namespace {

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

template <int N>
std::string vector_text(const glm::vec<N, double>& v) {
    std::string out = "[";
    for (int i = 0; i < N; ++i) out += (i ? ", " : "") + number(v[i]);
    return out + "]";
}

}  // namespace

std::string value_text(const TraceValue& value) {
    return std::visit(
        [](const auto& v) -> std::string {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, double>) return number(v);
            else if constexpr (std::is_same_v<V, std::string>) return v;
            else if constexpr (std::is_same_v<V, glm::dmat4>) {
                std::string out;
                for (int r = 0; r < 4; ++r) {
                    const glm::dvec4 x = row(v, r);
                    char line[128];
                    std::snprintf(line, sizeof line, "%s[%13.6g %13.6g %13.6g %13.6g]", r ? "\n" : "", x.x, x.y, x.z, x.w);
                    out += line;
                }
                return out;
            } else return vector_text(v);
        },
        value);
}

}  // namespace shadowlab
