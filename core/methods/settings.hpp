#pragma once
// A method's settings: each declared with its range or choices and a default, so the CLI, the GUI
// and the tests all read the same list.
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace shadowlab {

struct SettingSpec {
    std::string name;
    std::string description;
    std::string default_value;
    double min = 0.0, max = 0.0;       // numbers: the closed range
    std::vector<std::string> choices;  // choices: the allowed words (empty for a number)
    int length_power = 0;              // numbers: the unit, world length to this power (XPSM's coef: -1)
    bool is_list = false;              // numbers: a comma-separated list ("0.05,0.2,0.5"), each in the range
    bool is_text = false;              // free text taken as written (a file's path); no range, no choices

    bool is_choice() const { return !choices.empty(); }
};

class Settings {
public:
    double number(const std::string& name) const;
    const std::string& choice(const std::string& name) const;
    std::vector<double> numbers(const std::string& name) const;                      // a list setting, as given
    const std::string& text(const std::string& name) const { return choice(name); }  // a text setting
    const std::map<std::string, std::variant<double, std::string>>& values() const { return values_; }
    void set(const std::string& name, std::variant<double, std::string> value) { values_[name] = std::move(value); }

private:
    std::map<std::string, std::variant<double, std::string>> values_;
};

// Settings changed, and the change as users read it ("resolution_bias 0 → -2").
struct SettingsChange {
    Settings settings;
    std::string change;
};

// Defaults overridden by `overrides` (key -> text). Throws std::invalid_argument naming the method,
// the key and what is allowed, for an unknown key, a word not among the choices, a non-number or a
// number out of range (in a list: any of its numbers).
Settings resolve_settings(const std::string& method, const std::vector<SettingSpec>& specs,
                          const std::map<std::string, std::string>& overrides);

}  // namespace shadowlab
