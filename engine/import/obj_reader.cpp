// Wavefront OBJ: only the geometry (v and f statements) matters for a stone; texture
// coordinates, normals, materials, groups and smoothing are read past.

#include <string>

#include "geometry/triangulate.hpp"
#include "import/import_text.hpp"
#include "import/load_model.hpp"
#include "import/mesh_soup.hpp"

namespace gem {
namespace {

// Statements that carry nothing a stone needs (textures, normals, grouping, display hints).
bool ignored_statement(std::string_view keyword) {
    for (std::string_view k :
         {"vt", "vn", "vp", "usemtl", "mtllib", "o", "g", "s", "l", "p", "mg", "lod", "shadow_obj",
          "trace_obj", "bevel", "c_interp", "d_interp", "usemap", "maplib"}) {
        if (keyword == k) return true;
    }
    return false;
}

struct FaceCorner {
    long long index;  // as written: 1-based, or negative relative to the vertices so far
    std::size_t line;
};

}  // namespace

Result<Stone> load_obj(const std::filesystem::path& path) {
    auto bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    return parse_obj(bytes.value(), path);
}

Result<Stone> parse_obj(std::string_view text, const std::filesystem::path& path) {
    import::TriangleSoup soup;
    // Positive indices may refer to vertices written later, so they are checked at the end;
    // negative ones are relative to the vertices read so far and resolved at once.
    std::vector<std::vector<FaceCorner>> faces;
    import::LineCursor cursor(text);
    std::string_view line;
    while (cursor.next(line)) {
        const std::size_t at = cursor.line_number();
        const std::size_t hash = line.find('#');
        if (hash != std::string_view::npos) line = line.substr(0, hash);
        const auto tokens = import::split_tokens(line);
        if (tokens.empty()) continue;
        const std::string_view keyword = tokens[0];
        if (keyword == "v") {
            if (tokens.size() < 4) return import::line_error(path, at, "vertex needs x y z");
            glm::dvec3 p{0.0};
            for (int k = 0; k < 3; ++k) {
                const auto value = import::parse_number(tokens[std::size_t(k) + 1]);
                if (!value) {
                    return import::line_error(path, at,
                                              "vertex coordinate '" +
                                                  std::string(tokens[std::size_t(k) + 1]) +
                                                  "' is not a number");
                }
                p[k] = *value;
            }
            soup.positions.push_back(p);
        } else if (keyword == "f") {
            if (tokens.size() < 4) {
                return import::line_error(path, at, "face needs at least 3 vertices");
            }
            std::vector<FaceCorner> corners;
            for (std::size_t k = 1; k < tokens.size(); ++k) {
                // v, v/vt, v//vn and v/vt/vn: the vertex index is before the first slash.
                const std::string_view spec = tokens[k].substr(0, tokens[k].find('/'));
                const auto index = import::parse_integer(spec);
                if (!index || *index == 0) {
                    return import::line_error(
                        path, at,
                        "face vertex '" + std::string(tokens[k]) + "' is not a vertex index");
                }
                long long resolved = *index;
                if (resolved < 0) {
                    resolved += static_cast<long long>(soup.positions.size()) + 1;
                    if (resolved < 1) {
                        return import::line_error(
                            path, at,
                            "face index " + std::to_string(*index) + " out of range (" +
                                std::to_string(soup.positions.size()) + " vertices so far)");
                    }
                }
                corners.push_back({resolved, at});
            }
            faces.push_back(std::move(corners));
        } else if (!ignored_statement(keyword)) {
            return import::line_error(path, at, "unknown statement '" + std::string(keyword) + "'");
        }
    }
    // Polygons are triangulated once every vertex is known; ear clipping, because a face of a
    // gem model (a heart's table, a star) need not be convex.
    std::vector<std::uint32_t> loop;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (const auto& face : faces) {
        loop.clear();
        for (const FaceCorner& corner : face) {
            if (corner.index > static_cast<long long>(soup.positions.size())) {
                return import::line_error(path, corner.line,
                                          "face index " + std::to_string(corner.index) +
                                              " out of range (" +
                                              std::to_string(soup.positions.size()) + " vertices)");
            }
            loop.push_back(static_cast<std::uint32_t>(corner.index - 1));
        }
        if (loop.size() == 3) {
            soup.triangles.push_back({loop[0], loop[1], loop[2]});
            continue;
        }
        glm::dvec3 normal(0.0);  // Newell's method: the polygon's area vector
        for (std::size_t i = 0; i < loop.size(); ++i) {
            normal +=
                glm::cross(soup.positions[loop[i]], soup.positions[loop[(i + 1) % loop.size()]]);
        }
        if (glm::length(normal) == 0.0) {
            return import::line_error(path, face.front().line, "face has no area");
        }
        triangles.clear();
        triangulate_polygon(soup.positions, loop, normal, triangles);
        soup.triangles.insert(soup.triangles.end(), triangles.begin(), triangles.end());
    }
    return import::stone_from_soup(path, soup);
}

}  // namespace gem
