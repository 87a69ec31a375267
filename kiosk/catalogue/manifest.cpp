// Reads catalogue.toml with toml++ (https://marzer.github.io/tomlplusplus/), checking every key
// against the keys a table knows, so that a typo is an error and not a silently ignored line.
#include "catalogue/manifest.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "delivery/catalogue_files.hpp"
#include "piece/metal.hpp"

namespace gem::kiosk {

namespace {

using Problem = std::optional<Error>;

Error error_at(std::size_t line, std::string_view key, std::string_view what) {
    return Error{std::string(kManifestName) + ":" + std::to_string(line) + ": " + std::string(key) +
                 ": " + std::string(what)};
}
Error error_at(const toml::node& node, std::string_view key, std::string_view what) {
    return error_at(node.source().begin.line, key, what);
}

Problem read_string(const toml::node& node, std::string_view key, std::string& out) {
    if (!node.is_string()) return error_at(node, key, "expected a string");
    out = node.value<std::string>().value();
    if (out.empty()) return error_at(node, key, "must not be empty");
    return std::nullopt;
}

// A file of the catalogue: relative and without "..", so that it lies inside the directory.
Problem read_inner_path(const toml::node& node, std::string_view key,
                        const std::filesystem::path& dir, std::filesystem::path& out) {
    std::string text;
    if (auto e = read_string(node, key, text)) return e;
    const std::filesystem::path relative(text);
    if (relative.is_absolute()) {
        return error_at(node, key, "'" + text + "' must be relative to the catalogue directory");
    }
    for (const auto& part : relative) {
        if (part == "..") {
            return error_at(node, key, "'" + text + "' must not leave the catalogue directory");
        }
    }
    out = dir / relative.lexically_normal();
    return std::nullopt;
}

Problem read_rgb(const toml::node& node, std::string_view key, double max, glm::dvec3& out) {
    const toml::array* a = node.as_array();
    if (a == nullptr || a->size() != 3) return error_at(node, key, "expected [r, g, b]");
    for (std::size_t i = 0; i < 3; ++i) {
        const std::optional<double> v = (*a)[i].value<double>();
        if (!(*a)[i].is_number() || !v || !std::isfinite(*v)) {
            return error_at(node, key, "expected three finite numbers");
        }
        if (*v < 0.0 || *v > max) {
            return error_at(node, key,
                            max == 1.0 ? "components must be 0..1" : "components must be >= 0");
        }
        out[static_cast<int>(i)] = *v;
    }
    return std::nullopt;
}

// Rose gold is not among the metals, so it is refused by name rather than drawn as another.
Problem read_metal(const toml::node& node, Metal& out) {
    std::string text;
    if (auto e = read_string(node, "stone.metal", text)) return e;
    const std::optional<Metal> metal = parse_metal(text);
    if (!metal) {
        return error_at(node, "stone.metal",
                        "unknown metal '" + text + "' (this build has " + kMetalNames + ")");
    }
    out = *metal;
    return std::nullopt;
}

Problem read_stone(const toml::table& table, const std::filesystem::path& dir,
                   CatalogueStone& stone) {
    const std::size_t line = table.source().begin.line;
    // Keys a piece answers in its own file, and where they were given.
    std::vector<std::pair<std::string, std::size_t>> not_for_a_piece;
    for (auto&& [key, node] : table) {
        const std::string k(key.str());
        const std::string full = "stone." + k;
        if (k == "ring" || k == "metal" || k == "colour" || k == "absorption_per_mm") {
            not_for_a_piece.emplace_back(full, node.source().begin.line);
        }
        Problem e;
        if (k == "name") {
            e = read_string(node, full, stone.name);
        } else if (k == "database") {
            e = read_inner_path(node, full, dir, stone.database);
        } else if (k == "design") {
            e = read_inner_path(node, full, dir, stone.design);
        } else if (k == "piece") {
            e = read_inner_path(node, full, dir, stone.piece);
        } else if (k == "ring") {
            std::string text;
            e = read_string(node, full, text);
            if (e) return e;
            if (text == "parametric") {
                stone.ring = RingKind::parametric;
            } else if (text == "none") {
                stone.ring = RingKind::none;
            } else if (std::filesystem::path(text).extension() == ".obj") {
                stone.ring = RingKind::obj;
                e = read_inner_path(node, full, dir, stone.ring_obj);
            } else {
                return error_at(node, full,
                                "'" + text + "' is not parametric, none or a .obj file");
            }
        } else if (k == "metal") {
            e = read_metal(node, stone.metal);
        } else if (k == "colour") {
            glm::dvec3 v{};
            e = read_rgb(node, full, 1.0, v);
            stone.colour = v;
        } else if (k == "absorption_per_mm") {
            glm::dvec3 v{};
            e = read_rgb(node, full, HUGE_VAL, v);
            stone.absorption_per_mm = v;
        } else if (k == "background") {
            e = read_string(node, full, stone.background);
        } else if (k == "lighting") {
            e = read_string(node, full, stone.lighting);
        } else {
            e = error_at(key.source().begin.line, full, "unknown key");
        }
        if (e) return e;
    }
    if (stone.name.empty()) return error_at(line, "stone.name", "missing");
    const int sources =
        int(!stone.database.empty()) + int(!stone.design.empty()) + int(!stone.piece.empty());
    if (sources == 0) return error_at(line, "stone.database", "missing (or a design or a piece)");
    if (sources > 1) {
        return error_at(line, "stone", "give one of database, design and piece, not several");
    }
    // A piece brings its own setting, metal and stones' materials.
    if (!stone.piece.empty() && !not_for_a_piece.empty()) {
        return error_at(not_for_a_piece.front().second, not_for_a_piece.front().first,
                        "a piece gives its setting, metal and materials in its own file");
    }
    return std::nullopt;
}

// [blake2b]: "relative/file" = "<128 lowercase hex digits>" (delivery/catalogue_files.hpp).
Problem read_digests(const toml::node& node, std::map<std::string, std::string>& out) {
    const toml::table* t = node.as_table();
    if (t == nullptr) return error_at(node, "blake2b", "expected a table [blake2b]");
    for (auto&& [key, value] : *t) {
        const std::string name(key.str());
        const std::string full = "blake2b.\"" + name + "\"";
        if (!tables::is_catalogue_file_name(name)) {
            return error_at(key.source().begin.line, full,
                            "must name a file inside the catalogue directory");
        }
        const std::optional<std::string> digest = value.value<std::string>();
        const bool hex = digest && digest->size() == 128 &&
                         digest->find_first_not_of("0123456789abcdef") == std::string::npos;
        if (!value.is_string() || !hex) {
            return error_at(value, full,
                            "expected a BLAKE2b-512 digest (128 lowercase hex digits)");
        }
        out[name] = *digest;
    }
    return std::nullopt;
}

}  // namespace

Result<std::string> read_manifest_text(const std::filesystem::path& dir) {
    const std::filesystem::path path = dir / kManifestName;
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{std::string(kManifestName) + ": " + std::strerror(errno)};
    // A manifest names a few dozen stones; a file far larger is not one.
    constexpr std::size_t kLargest = 16 << 20;
    std::string text(kLargest + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) return Error{std::string(kManifestName) + ": read error"};
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > kLargest) return Error{std::string(kManifestName) + ": larger than 16 MiB"};
    return text;
}

Result<Catalogue> read_manifest(const std::filesystem::path& dir) {
    Result<std::string> text = read_manifest_text(dir);
    if (!text) return Error{text.error()};
    return parse_manifest(text.value(), dir);
}

Result<Catalogue> parse_manifest(std::string_view text, const std::filesystem::path& dir) {
    toml::table doc;
    try {
        doc = toml::parse(text, (dir / kManifestName).string());
    } catch (const toml::parse_error& err) {
        return error_at(err.source().begin.line, "syntax", err.description());
    }
    Catalogue catalogue;
    catalogue.directory = dir;
    for (auto&& [key, node] : doc) {
        const std::string k(key.str());
        if (k == "catalogue") {
            const toml::table* t = node.as_table();
            if (t == nullptr) return error_at(node, k, "expected a table [catalogue]");
            for (auto&& [inner, value] : *t) {
                const std::string full = "catalogue." + std::string(inner.str());
                if (inner.str() != "name") {
                    return error_at(inner.source().begin.line, full, "unknown key");
                }
                if (auto e = read_string(value, full, catalogue.name)) return *e;
            }
        } else if (k == "stone") {
            const toml::array* stones = node.as_array();
            if (stones == nullptr || !stones->is_array_of_tables()) {
                return error_at(node, k, "expected [[stone]] tables");
            }
            std::set<std::string> names;
            for (const toml::node& entry : *stones) {
                CatalogueStone stone;
                if (auto e = read_stone(*entry.as_table(), dir, stone)) return *e;
                if (!names.insert(stone.name).second) {
                    const toml::node& name = *entry.as_table()->get("name");
                    return error_at(name, "stone.name", "'" + stone.name + "' appears twice");
                }
                catalogue.stones.push_back(std::move(stone));
            }
        } else if (k == "blake2b") {
            if (auto e = read_digests(node, catalogue.digests)) return *e;
        } else {
            return error_at(key.source().begin.line, k, "unknown key");
        }
    }
    if (catalogue.name.empty()) return error_at(1, "catalogue.name", "missing");
    if (catalogue.stones.empty()) return error_at(1, "stone", "no [[stone]] entries");
    return catalogue;
}

}  // namespace gem::kiosk
