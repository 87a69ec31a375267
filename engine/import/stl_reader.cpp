// STL, ASCII and binary. Binary: an 80-byte header, a little-endian uint32 triangle count,
// then 50 bytes per triangle (normal, three vertices as float32, a uint16 attribute).
// Some binary writers start the header with "solid", so the file size decides.

#include <bit>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <string>

#include "import/import_text.hpp"
#include "import/load_model.hpp"
#include "import/mesh_soup.hpp"

namespace gem {
namespace {

constexpr std::size_t kHeaderBytes = 84;
constexpr std::size_t kTriangleBytes = 50;

std::uint32_t read_u32_le(const char* p) {
    const auto* b = reinterpret_cast<const unsigned char*>(p);
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
           std::uint32_t(b[3]) << 24;
}

float read_f32_le(const char* p) {
    return std::bit_cast<float>(read_u32_le(p));
}

bool binary_size_matches(std::string_view bytes) {
    if (bytes.size() < kHeaderBytes) return false;
    const std::uint64_t count = read_u32_le(bytes.data() + 80);
    return bytes.size() == kHeaderBytes + kTriangleBytes * count;
}

bool starts_with_solid(std::string_view bytes) {
    std::size_t i = 0;
    while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
    return import::istarts_with(bytes.substr(i), "solid");
}

Result<Stone> read_binary(const std::filesystem::path& path, std::string_view bytes) {
    if (bytes.size() < kHeaderBytes) {
        return import::file_error(path, "truncated binary STL: " + std::to_string(bytes.size()) +
                                            " bytes, the header alone takes 84");
    }
    const std::uint64_t count = read_u32_le(bytes.data() + 80);
    const std::uint64_t expected = kHeaderBytes + kTriangleBytes * count;
    if (bytes.size() != expected) {
        return import::file_error(
            path, std::string(bytes.size() < expected ? "truncated" : "oversized") +
                      " binary STL: header says " + std::to_string(count) + " triangles (" +
                      std::to_string(expected) + " bytes) but the file has " +
                      std::to_string(bytes.size()) + " bytes");
    }
    import::TriangleSoup soup;
    soup.positions.reserve(3 * count);
    for (std::uint64_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + kHeaderBytes + kTriangleBytes * t;
        // The stored normal is skipped: the winding says which side is out.
        for (std::uint32_t k = 0; k < 3; ++k) {
            const char* v = record + 12 + 12 * k;
            soup.positions.emplace_back(read_f32_le(v), read_f32_le(v + 4), read_f32_le(v + 8));
        }
        const auto base = static_cast<std::uint32_t>(3 * t);
        soup.triangles.push_back({base, base + 1, base + 2});
    }
    return import::stone_from_soup(path, soup);
}

// solid name / facet normal ... / outer loop / vertex x y z (3 or more) / endloop / endfacet /
// endsolid, possibly several solids, which are merged.
Result<Stone> read_ascii(const std::filesystem::path& path, std::string_view text) {
    enum class State { outside, in_solid, in_facet, in_loop };
    State state = State::outside;
    import::TriangleSoup soup;
    std::vector<std::uint32_t> loop;
    import::LineCursor cursor(text);
    std::string_view line;
    auto unexpected = [&](std::string_view keyword) {
        return import::line_error(path, cursor.line_number(),
                                  "unexpected '" + std::string(keyword) + "'");
    };
    while (cursor.next(line)) {
        const auto tokens = import::split_tokens(line);
        if (tokens.empty()) continue;
        const std::string_view k = tokens[0];
        if (import::iequals(k, "solid")) {
            if (state != State::outside) return unexpected(k);
            state = State::in_solid;
        } else if (import::iequals(k, "facet")) {
            if (state != State::in_solid) return unexpected(k);
            state = State::in_facet;
        } else if (import::iequals(k, "outer")) {
            if (state != State::in_facet) return unexpected(k);
            state = State::in_loop;
            loop.clear();
        } else if (import::iequals(k, "vertex")) {
            if (state != State::in_loop) return unexpected(k);
            if (tokens.size() != 4) {
                return import::line_error(path, cursor.line_number(), "vertex needs x y z");
            }
            glm::dvec3 p{0.0};
            for (int c = 0; c < 3; ++c) {
                const auto value = import::parse_number(tokens[std::size_t(c) + 1]);
                if (!value) {
                    return import::line_error(path, cursor.line_number(),
                                              "vertex coordinate '" +
                                                  std::string(tokens[std::size_t(c) + 1]) +
                                                  "' is not a number");
                }
                p[c] = *value;
            }
            loop.push_back(static_cast<std::uint32_t>(soup.positions.size()));
            soup.positions.push_back(p);
        } else if (import::iequals(k, "endloop")) {
            if (state != State::in_loop) return unexpected(k);
            if (loop.size() < 3) {
                return import::line_error(
                    path, cursor.line_number(),
                    "loop has " + std::to_string(loop.size()) + " vertices, needs at least 3");
            }
            for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
                soup.triangles.push_back({loop[0], loop[i], loop[i + 1]});
            }
            state = State::in_facet;
        } else if (import::iequals(k, "endfacet")) {
            if (state != State::in_facet) return unexpected(k);
            state = State::in_solid;
        } else if (import::iequals(k, "endsolid")) {
            if (state != State::in_solid) return unexpected(k);
            state = State::outside;
        } else {
            return import::line_error(path, cursor.line_number(),
                                      "unknown keyword '" + std::string(k) + "'");
        }
    }
    if (state != State::outside) {
        return import::line_error(path, cursor.line_number(),
                                  "truncated ASCII STL: the file ends before 'endsolid'");
    }
    return import::stone_from_soup(path, soup);
}

}  // namespace

Result<Stone> load_stl(const std::filesystem::path& path) {
    auto bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    return parse_stl(bytes.value(), path);
}

Result<Stone> parse_stl(std::string_view b, const std::filesystem::path& path) {
    if (b.empty()) return import::file_error(path, "empty file");
    // Text never holds NUL bytes, while a binary count or float almost always does.
    const bool binary =
        binary_size_matches(b) || !starts_with_solid(b) || b.find('\0') != std::string_view::npos;
    if (binary) return read_binary(path, b);
    return read_ascii(path, b);
}

}  // namespace gem
