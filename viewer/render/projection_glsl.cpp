#include "render/projection_glsl.hpp"

#include <set>

#include "maps/projection_kind.hpp"
#include "render/glsl_source.hpp"

namespace shadowlab {
namespace {

// A function the shaders call on map i, and what it returns for a kind without it.
struct KindFunction {
    const char* name;       // the shaders' name of it
    const char* suffix;     // the kind's own: <glsl_prefix><suffix>
    const char* signature;  // "vec4 (int i, vec3 p)" without the name
    const char* arguments;  // "i, p"
    const char* otherwise;  // for a kind without it (nullptr: every kind has it)
    bool (*has)(const ProjectionKind&);
};

bool always(const ProjectionKind&) { return true; }
bool clips(const ProjectionKind& kind) { return kind.clip_distance != nullptr; }

const KindFunction kFunctions[] = {
    {"shadowHomogeneous", "Homogeneous", "vec4 %(int i, vec3 p)", "i, p", nullptr, always},
    {"shadowHemisphereSide", "ClipDistance", "float %(int i, vec3 p)", "i, p", "1.0", clips},
    {"shadowUvDerivative", "UvDerivative", "vec2 %(int i, vec3 p, vec3 direction)", "i, p, direction", nullptr, always},
    {"shadowDepthSlope", "DepthSlope", "float %(int i, vec3 l, vec3 p)", "i, l, p", nullptr, always},
    {"shadowDistanceBackToDepth", "DistanceBackToDepth", "float %(int i, vec3 l, vec3 p, float depth)",
     "i, l, p, depth", nullptr, always},
};

std::string declaration(const KindFunction& f) {
    std::string signature = f.signature;
    return signature.replace(signature.find('%'), 1, f.name);
}

// One line per kind: `if (shadowMapProjection[i] == k) return ...;`.
std::string dispatch(const KindFunction& f) {
    std::string out = declaration(f) + " {\n";
    for (Projection projection : projection_kinds()) {
        const ProjectionKind& kind = projection_kind(projection);
        const std::string call =
            f.has(kind) ? std::string(kind.glsl_prefix) + f.suffix + "(" + f.arguments + ")" : std::string(f.otherwise);
        out += "  if (shadowMapProjection[i] == " + std::to_string(int(projection)) + ") return " + call + ";\n";
    }
    return out + "  return " + declaration(f).substr(0, declaration(f).find(' ')) + "(0.0);  // no such kind\n}\n";
}

}  // namespace

std::string projection_glsl() {
    std::string out;
    std::set<std::string> included;
    for (Projection projection : projection_kinds())
        if (const char* file = projection_kind(projection).glsl; included.insert(file).second)
            out += std::string(glsl_source(file));
    for (const KindFunction& f : kFunctions) out += dispatch(f);
    return out;
}

}  // namespace shadowlab
