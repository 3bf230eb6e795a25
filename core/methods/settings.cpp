#include "methods/settings.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace shadowlab {

double Settings::number(const std::string& name) const {
    return std::get<double>(values_.at(name));
}

const std::string& Settings::choice(const std::string& name) const {
    return std::get<std::string>(values_.at(name));
}

namespace {

std::variant<double, std::string> parse_value(const std::string& method, const SettingSpec& spec,
                                              const std::string& text) {
    std::ostringstream problem;
    problem << "method " << method << ": setting " << spec.name << "=" << text << ": ";
    if (spec.is_choice()) {
        for (const std::string& c : spec.choices)
            if (c == text) return text;
        problem << "expected one of";
        for (const std::string& c : spec.choices) problem << " " << c;
        throw std::invalid_argument(problem.str());
    }
    size_t used = 0;
    double value = NAN;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !std::isfinite(value) || value < spec.min || value > spec.max) {
        problem << "expected a number in [" << spec.min << ", " << spec.max << "]";
        throw std::invalid_argument(problem.str());
    }
    return value;
}

}  // namespace

Settings resolve_settings(const std::string& method, const std::vector<SettingSpec>& specs,
                          const std::map<std::string, std::string>& overrides) {
    Settings settings;
    for (const SettingSpec& spec : specs) {
        auto given = overrides.find(spec.name);
        settings.set(spec.name,
                     parse_value(method, spec, given == overrides.end() ? spec.default_value : given->second));
    }
    for (const auto& [key, value] : overrides)
        if (!settings.values().count(key)) {
            std::string known;
            for (const SettingSpec& spec : specs) known += (known.empty() ? "" : ", ") + spec.name;
            throw std::invalid_argument("method " + method + ": unknown setting '" + key +
                                        "' (known: " + (known.empty() ? "none" : known) + ")");
        }
    return settings;
}

}  // namespace shadowlab
