#include "settings/config_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gem::kiosk {

namespace {

// toml++ keeps integers as int64 and floats as double; a number key accepts either.
bool finite_number(const toml::node& node, double& out) {
    if (!node.is_number()) return false;
    out = node.value<double>().value();
    return std::isfinite(out);
}

std::string format_number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

}  // namespace

void ConfigReader::error(std::size_t line, std::string_view key, std::string_view what) {
    problems_.push_back(Problem{line, name_ + ":" + std::to_string(line) + ": " + std::string(key) +
                                          ": " + std::string(what)});
}

std::vector<std::string> ConfigReader::take_errors() {
    std::stable_sort(problems_.begin(), problems_.end(),
                     [](const Problem& a, const Problem& b) { return a.line < b.line; });
    std::vector<std::string> messages;
    messages.reserve(problems_.size());
    for (Problem& p : problems_) messages.push_back(std::move(p.message));
    problems_.clear();
    return messages;
}

bool ConfigReader::string(const toml::node& node, std::string_view key, std::string& out) {
    if (!node.is_string()) {
        error(node, key, "expected a string");
        return false;
    }
    out = node.value<std::string>().value();
    return true;
}

bool ConfigReader::boolean(const toml::node& node, std::string_view key, bool& out) {
    if (!node.is_boolean()) {
        error(node, key, "expected true or false");
        return false;
    }
    out = node.value<bool>().value();
    return true;
}

bool ConfigReader::integer(const toml::node& node, std::string_view key, long long lo, long long hi,
                           int& out) {
    if (!node.is_integer()) {
        error(node, key, "expected an integer");
        return false;
    }
    const long long v = node.value<long long>().value();
    if (v < lo || v > hi) {
        error(node, key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
        return false;
    }
    out = static_cast<int>(v);
    return true;
}

bool ConfigReader::integer_of(const toml::node& node, std::string_view key,
                              std::initializer_list<int> set, int& out) {
    if (node.is_integer()) {
        const long long v = node.value<long long>().value();
        if (std::find(set.begin(), set.end(), v) != set.end()) {
            out = static_cast<int>(v);
            return true;
        }
    }
    std::string what = "expected one of ";
    for (const int* i = set.begin(); i != set.end(); ++i) {
        if (i != set.begin()) what += ", ";
        what += std::to_string(*i);
    }
    error(node, key, what);
    return false;
}

bool ConfigReader::number(const toml::node& node, std::string_view key, double lo, double hi,
                          double& out) {
    double v = 0.0;
    if (!finite_number(node, v)) {
        error(node, key, "expected a finite number");
        return false;
    }
    if (!(v >= lo && v <= hi)) {
        error(node, key, "must be between " + format_number(lo) + " and " + format_number(hi));
        return false;
    }
    out = v;
    return true;
}

bool ConfigReader::positive(const toml::node& node, std::string_view key, double& out) {
    double v = 0.0;
    if (!finite_number(node, v)) {
        error(node, key, "expected a finite number");
        return false;
    }
    if (!(v > 0.0)) {
        error(node, key, "must be positive");
        return false;
    }
    out = v;
    return true;
}

bool ConfigReader::choice(const toml::node& node, std::string_view key,
                          std::initializer_list<std::string_view> names, std::size_t& index) {
    return choice(node, key, std::span<const std::string_view>(names.begin(), names.size()), index);
}

bool ConfigReader::choice(const toml::node& node, std::string_view key,
                          std::span<const std::string_view> names, std::size_t& index) {
    if (const auto text = node.value<std::string_view>()) {
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (names.begin()[i] == *text) {
                index = i;
                return true;
            }
        }
    }
    std::string what = "expected one of ";
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i != 0) what += ", ";
        what += "\"" + std::string(names.begin()[i]) + "\"";
    }
    error(node, key, what);
    return false;
}

bool ConfigReader::strings(const toml::node& node, std::string_view key,
                           std::vector<std::string>& out) {
    const toml::array* array = node.as_array();
    std::vector<std::string> values;
    if (array != nullptr) {
        for (const toml::node& item : *array) {
            if (!item.is_string()) break;
            values.push_back(item.value<std::string>().value());
        }
    }
    if (array == nullptr || values.size() != array->size()) {
        error(node, key, "expected a list of strings");
        return false;
    }
    out = std::move(values);
    return true;
}

bool ConfigReader::numbers(const toml::node& node, std::string_view key, std::span<double> out) {
    const toml::array* array = node.as_array();
    bool good = array != nullptr && array->size() == out.size();
    std::vector<double> values(out.size());
    for (std::size_t i = 0; good && i < out.size(); ++i)
        good = finite_number((*array)[i], values[i]);
    if (!good) {
        error(node, key, "expected a list of " + std::to_string(out.size()) + " finite numbers");
        return false;
    }
    std::copy(values.begin(), values.end(), out.begin());
    return true;
}

bool ConfigReader::vec3(const toml::node& node, std::string_view key, glm::dvec3& out) {
    double v[3] = {0.0, 0.0, 0.0};
    if (!numbers(node, key, v)) return false;
    out = glm::dvec3(v[0], v[1], v[2]);
    return true;
}

bool ConfigReader::colour(const toml::node& node, std::string_view key, glm::dvec3& out) {
    glm::dvec3 v(0.0);
    if (!vec3(node, key, v)) return false;
    if (v.x < 0.0 || v.y < 0.0 || v.z < 0.0) {
        error(node, key, "colour components must not be negative");
        return false;
    }
    out = v;
    return true;
}

std::filesystem::path ConfigReader::resolve(const std::string& text) const {
    const std::filesystem::path p(text);
    return p.is_relative() ? base_dir_ / p : p;
}

bool ConfigReader::path(const toml::node& node, std::string_view key, std::filesystem::path& out) {
    std::string text;
    if (!string(node, key, text)) return false;
    if (text.empty()) {
        error(node, key, "expected a path, not an empty string");
        return false;
    }
    out = resolve(text);
    return true;
}

bool ConfigReader::paths(const toml::node& node, std::string_view key,
                         std::vector<std::filesystem::path>& out) {
    std::vector<std::string> texts;
    if (!strings(node, key, texts)) return false;
    std::vector<std::filesystem::path> resolved;
    for (const std::string& text : texts) {
        if (text.empty()) {
            error(node, key, "expected paths, not an empty string");
            return false;
        }
        resolved.push_back(resolve(text));
    }
    out = std::move(resolved);
    return true;
}

}  // namespace gem::kiosk
