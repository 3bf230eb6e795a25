#include "methods/settings.hpp"

#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace shadowlab {

double Settings::number(const std::string& name) const { return std::get<double>(values_.at(name)); }

const std::string& Settings::choice(const std::string& name) const { return std::get<std::string>(values_.at(name)); }

namespace {

// The number `text` spells exactly, finite and within the spec's range; nullopt otherwise.
std::optional<double> number_in_range(const SettingSpec& spec, const std::string& text) {
    size_t used = 0;
    double value = NAN;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (used != text.size() || !std::isfinite(value) || value < spec.min || value > spec.max) return std::nullopt;
    return value;
}

// The comma-separated parts of a list's text ("" has none).
std::vector<std::string> list_items(const std::string& text) {
    std::vector<std::string> items;
    std::istringstream in(text);
    for (std::string item; std::getline(in, item, ',');) items.push_back(item);
    return items;
}

std::variant<double, std::string> parse_value(const std::string& method, const SettingSpec& spec,
                                              const std::string& text) {
    std::ostringstream problem;
    problem << "method " << method << ": setting " << spec.name << "=" << text << ": ";
    if (spec.is_text) return text;
    if (spec.is_choice()) {
        for (const std::string& c : spec.choices)
            if (c == text) return text;
        problem << "expected one of";
        for (const std::string& c : spec.choices) problem << " " << c;
        throw std::invalid_argument(problem.str());
    }
    if (spec.is_list) {
        for (const std::string& item : list_items(text))
            if (!number_in_range(spec, item)) {
                problem << "expected comma-separated numbers in [" << spec.min << ", " << spec.max << "]";
                throw std::invalid_argument(problem.str());
            }
        return text;  // kept as written; numbers() reads it
    }
    if (const std::optional<double> value = number_in_range(spec, text)) return *value;
    problem << "expected a number in [" << spec.min << ", " << spec.max << "]";
    throw std::invalid_argument(problem.str());
}

}  // namespace

std::vector<double> Settings::numbers(const std::string& name) const {
    std::vector<double> numbers;
    for (const std::string& item : list_items(choice(name))) numbers.push_back(std::stod(item));
    return numbers;
}

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
