#include "views/view_options.hpp"

namespace shadowlab {

const char* to_string(SpacePreset preset) {
    switch (preset) {
        case SpacePreset::orbit: return "orbit";
        case SpacePreset::from_light: return "light";
        case SpacePreset::side: return "side";
    }
    return "?";
}

const std::vector<SpacePreset>& all_space_presets() {
    static const std::vector<SpacePreset> presets{SpacePreset::orbit, SpacePreset::from_light, SpacePreset::side};
    return presets;
}

std::optional<SpacePreset> space_preset_named(const std::string& name) {
    for (SpacePreset p : all_space_presets())
        if (name == to_string(p)) return p;
    return std::nullopt;
}

const std::vector<ErrorChoice>& all_error_choices() {
    static const std::vector<ErrorChoice> choices{{ErrorShown::automatic, "auto", "Automatic"},
                                                  {ErrorShown::verdicts, "verdicts", "Verdicts"},
                                                  {ErrorShown::signed_visibility, "signed", "Signed visibility"},
                                                  {ErrorShown::causes, "causes", "Causes"}};
    return choices;
}

std::optional<ErrorShown> error_shown_named(const std::string& name) {
    for (const ErrorChoice& c : all_error_choices())
        if (name == c.name) return c.shown;
    return std::nullopt;
}

bool soft_shadows(const Inspection& in) {
    return in.scene.light.is_area() || (in.has_map() && in.lookup.filter.soft());
}

bool shows_signed_error(const Inspection& in, ErrorShown shown) {
    return shown == ErrorShown::automatic ? soft_shadows(in) : shown == ErrorShown::signed_visibility;
}

bool shows_aliasing(const Inspection& in, ErrorShown shown) {
    return in.has_map() && shown != ErrorShown::causes && !shows_signed_error(in, shown);
}

}  // namespace shadowlab
