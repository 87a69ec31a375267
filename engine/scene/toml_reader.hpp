#pragma once
// Reading the engine's TOML files (scenes, stone descriptions, pieces) with toml++: each value
// checked for its type and range, and every error naming the file, the line and the dotted key,
// e.g. "halo.toml:7: small.gap_mm: expected a number". Only the engine's own sources include
// this (toml++ is private to the engine library).

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

#include <toml++/toml.h>
#include <glm/glm.hpp>

#include "util/result.hpp"

namespace gem {

// The document, or "name:line: what toml++ found wrong".
inline Result<toml::table> parse_toml(std::string_view text, const std::string& name) {
    try {
        return toml::parse(text, name);
    } catch (const toml::parse_error& err) {
        return Error{name + ":" + std::to_string(err.source().begin.line) + ": " +
                     std::string(err.description())};
    }
}

class Reader {
  public:
    Reader(std::string name, std::filesystem::path base)
        : name_(std::move(name)), base_(std::move(base)) {}

    Error error(const toml::node& node, std::string_view key, std::string_view what) const {
        return error_at(node.source().begin.line, key, what);
    }
    Error error_at(std::size_t line, std::string_view key, std::string_view what) const {
        return Error{name_ + ":" + std::to_string(line) + ": " + std::string(key) + ": " +
                     std::string(what)};
    }

    std::optional<Error> number(const toml::node& n, std::string_view key, double& out) const {
        if (!n.is_number()) return error(n, key, "expected a number");
        out = n.value<double>().value();
        // TOML allows nan and inf; no key of a scene means anything with them.
        if (!std::isfinite(out)) return error(n, key, "expected a finite number");
        return std::nullopt;
    }
    std::optional<Error> number_in(const toml::node& n, std::string_view key, double lo, double hi,
                                   double& out) const {
        if (auto e = number(n, key, out)) return e;
        if (!(out >= lo && out <= hi)) {
            std::ostringstream what;
            what << "must be between " << lo << " and " << hi;
            return error(n, key, what.str());
        }
        return std::nullopt;
    }
    std::optional<Error> positive(const toml::node& n, std::string_view key, double& out) const {
        if (auto e = number(n, key, out)) return e;
        if (!(out > 0.0)) return error(n, key, "must be positive");
        return std::nullopt;
    }
    std::optional<Error> integer(const toml::node& n, std::string_view key, long long lo,
                                 long long hi, int& out) const {
        if (!n.is_integer()) return error(n, key, "expected an integer");
        const long long v = n.value<long long>().value();
        if (v < lo || v > hi) {
            return error(n, key,
                         "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
        }
        out = static_cast<int>(v);
        return std::nullopt;
    }
    std::optional<Error> boolean(const toml::node& n, std::string_view key, bool& out) const {
        if (!n.is_boolean()) return error(n, key, "expected true or false");
        out = n.value<bool>().value();
        return std::nullopt;
    }
    std::optional<Error> string(const toml::node& n, std::string_view key, std::string& out) const {
        if (!n.is_string()) return error(n, key, "expected a string");
        out = n.value<std::string>().value();
        return std::nullopt;
    }
    std::optional<Error> vec3(const toml::node& n, std::string_view key, glm::dvec3& out) const {
        const toml::array* a = n.as_array();
        if (a == nullptr || a->size() != 3) return error(n, key, "expected [x, y, z]");
        for (std::size_t i = 0; i < 3; ++i) {
            if (!(*a)[i].is_number()) return error(n, key, "expected three numbers");
            out[static_cast<int>(i)] = (*a)[i].value<double>().value();
            if (!std::isfinite(out[static_cast<int>(i)])) {
                return error(n, key, "expected three finite numbers");
            }
        }
        return std::nullopt;
    }
    std::optional<Error> colour(const toml::node& n, std::string_view key, glm::dvec3& out) const {
        if (auto e = vec3(n, key, out)) return e;
        if (out.x < 0.0 || out.y < 0.0 || out.z < 0.0) {
            return error(n, key, "colour components must not be negative");
        }
        return std::nullopt;
    }
    std::filesystem::path path(const std::string& text) const {
        const std::filesystem::path p(text);
        return p.is_relative() && !base_.empty() ? base_ / p : p;
    }
    std::optional<Error> unknown(const toml::key& key, std::string_view table) const {
        const std::string full = table.empty() ? std::string(key.str())
                                               : std::string(table) + "." + std::string(key.str());
        return error_at(key.source().begin.line, full, "unknown key");
    }

  private:
    std::string name_;
    std::filesystem::path base_;
};

}  // namespace gem
