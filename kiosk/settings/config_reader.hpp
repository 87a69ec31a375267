#pragma once
// Private to the settings library: typed reading of one TOML value with range checks. Every
// reader either stores the value and returns true, or records one error naming the file, the
// line and the key and returns false, leaving the target (its default) untouched.

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>
#include <glm/vec3.hpp>

namespace gem::kiosk {

class ConfigReader {
  public:
    ConfigReader(std::string name, std::filesystem::path base_dir)
        : name_(std::move(name)), base_dir_(std::move(base_dir)) {}

    void error(std::size_t line, std::string_view key, std::string_view what);
    void error(const toml::node& node, std::string_view key, std::string_view what) {
        error(node.source().begin.line, key, what);
    }
    // The messages, ordered by line (the loader visits keys in name order, not file order).
    std::vector<std::string> take_errors();

    bool string(const toml::node& node, std::string_view key, std::string& out);
    bool boolean(const toml::node& node, std::string_view key, bool& out);
    bool integer(const toml::node& node, std::string_view key, long long lo, long long hi,
                 int& out);
    // An integer from a small set, e.g. rotations: "expected one of 0, 90, 180, 270".
    bool integer_of(const toml::node& node, std::string_view key, std::initializer_list<int> set,
                    int& out);
    // A finite number (integer or float) in [lo, hi].
    bool number(const toml::node& node, std::string_view key, double lo, double hi, double& out);
    // A finite number > 0.
    bool positive(const toml::node& node, std::string_view key, double& out);
    // One of `names`; `index` receives its position.
    bool choice(const toml::node& node, std::string_view key,
                std::initializer_list<std::string_view> names, std::size_t& index);
    bool choice(const toml::node& node, std::string_view key,
                std::span<const std::string_view> names, std::size_t& index);
    bool strings(const toml::node& node, std::string_view key, std::vector<std::string>& out);
    bool numbers(const toml::node& node, std::string_view key, std::span<double> out);
    bool vec3(const toml::node& node, std::string_view key, glm::dvec3& out);
    // Three finite numbers, none negative (linear RGB).
    bool colour(const toml::node& node, std::string_view key, glm::dvec3& out);
    // A non-empty string; relative paths are taken relative to the config file's folder.
    bool path(const toml::node& node, std::string_view key, std::filesystem::path& out);
    bool paths(const toml::node& node, std::string_view key,
               std::vector<std::filesystem::path>& out);

  private:
    struct Problem {
        std::size_t line = 0;
        std::string message;
    };
    std::filesystem::path resolve(const std::string& text) const;

    std::string name_;
    std::filesystem::path base_dir_;
    std::vector<Problem> problems_;
};

// A key a table knows and how its value is read into the target.
template <class Target>
struct KeySpec {
    std::string_view name;
    void (*read)(ConfigReader& reader, const toml::node& value, std::string_view key,
                 Target& target);
};

// Reads every key of `node` (which must be a table) with the spec of the same name; unknown
// keys are errors. `prefix` is the table's dotted name ("display", "lighting.light").
template <class Target>
void read_table(ConfigReader& reader, const toml::node& node, std::string_view prefix,
                std::span<const KeySpec<Target>> specs, Target& target) {
    const toml::table* table = node.as_table();
    if (table == nullptr) {
        reader.error(node, prefix, "expected a table");
        return;
    }
    for (auto&& [key, value] : *table) {
        const std::string full = std::string(prefix) + "." + std::string(key.str());
        const KeySpec<Target>* spec = nullptr;
        for (const KeySpec<Target>& s : specs) {
            if (s.name == key.str()) spec = &s;
        }
        if (spec == nullptr) {
            reader.error(key.source().begin.line, full, "unknown key");
            continue;
        }
        spec->read(reader, value, full, target);
    }
}

// Appends "prefix.name" for every key of `specs` (for known_config_keys()).
template <class Target, std::size_t N>
void append_keys(std::vector<std::string>& keys, std::string_view prefix,
                 const KeySpec<Target> (&specs)[N]) {
    for (const KeySpec<Target>& s : specs)
        keys.push_back(std::string(prefix) + "." + std::string(s.name));
}

}  // namespace gem::kiosk
