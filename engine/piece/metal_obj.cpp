#include "piece/metal_obj.hpp"

#include <array>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "import/import_text.hpp"

namespace gem {

Result<MetalMesh> load_metal_obj(const std::filesystem::path& path, Metal metal, double roughness) {
    auto bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    return parse_metal_obj(bytes.value(), path, metal, roughness);
}

Result<MetalMesh> parse_metal_obj(std::string_view text, const std::filesystem::path& path,
                                  Metal metal, double roughness) {
    if (!(roughness >= 0.0 && roughness <= 1.0)) {
        return Error{path.string() + ": roughness must be 0..1"};
    }
    std::vector<glm::dvec3> v;
    std::vector<glm::dvec3> vn;
    struct Corner {
        long long v, n;  // 0-based; n = -1 without a normal
    };
    std::vector<std::array<Corner, 3>> triangles;
    std::vector<std::size_t> triangle_line;
    import::LineCursor cursor(text);
    std::string_view line;
    auto resolve = [](long long index, std::size_t count) -> long long {
        // 1-based, or negative: relative to the elements read so far.
        return index > 0 ? index - 1 : static_cast<long long>(count) + index;
    };
    while (cursor.next(line)) {
        const std::size_t at = cursor.line_number();
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
            line = line.substr(0, hash);
        }
        const auto tokens = import::split_tokens(line);
        if (tokens.empty()) continue;
        const std::string_view key = tokens[0];
        if (key == "v" || key == "vn") {
            if (tokens.size() < 4)
                return import::line_error(path, at, std::string(key) + " needs x y z");
            glm::dvec3 p(0.0);
            for (int k = 0; k < 3; ++k) {
                const auto value = import::parse_number(tokens[std::size_t(k) + 1]);
                if (!value) {
                    return import::line_error(
                        path, at,
                        "'" + std::string(tokens[std::size_t(k) + 1]) + "' is not a number");
                }
                p[k] = *value;
            }
            if (key == "v" && !(glm::length(p) <= kFarthestCornerMm)) {
                char far[160];
                std::snprintf(far, sizeof far,
                              "the vertex lies %.3g mm from the stone's centre (at most %.0f mm: a "
                              "ring is drawn in the stone frame, in millimetres)",
                              glm::length(p), kFarthestCornerMm);
                return import::line_error(path, at, far);
            }
            (key == "v" ? v : vn).push_back(p);
        } else if (key == "f") {
            if (tokens.size() < 4)
                return import::line_error(path, at, "face needs at least 3 vertices");
            std::vector<Corner> corners;
            for (std::size_t k = 1; k < tokens.size(); ++k) {
                const std::string_view spec = tokens[k];
                const std::size_t slash = spec.find('/');
                const auto vi = import::parse_integer(spec.substr(0, slash));
                long long ni = -1;
                const std::size_t last = spec.rfind('/');
                bool ok = vi && *vi != 0;
                if (ok && slash != std::string_view::npos && last != slash) {
                    const auto n = import::parse_integer(spec.substr(last + 1));
                    ok = n && *n != 0;
                    if (ok) ni = resolve(*n, vn.size());
                    if (ok && (ni < 0 || ni >= static_cast<long long>(vn.size()))) {
                        return import::line_error(path, at,
                                                  "normal index in '" + std::string(spec) +
                                                      "' out of range (" +
                                                      std::to_string(vn.size()) + " normals)");
                    }
                }
                if (!ok) {
                    return import::line_error(
                        path, at, "face vertex '" + std::string(spec) + "' is not a vertex index");
                }
                const long long vr = resolve(*vi, v.size());
                // Unlike a stone's OBJ, a ring's faces may only use vertices written before them:
                // that is what exporters write, and it lets the error name the line.
                if (vr < 0 || vr >= static_cast<long long>(v.size())) {
                    return import::line_error(path, at,
                                              "face index " + std::to_string(*vi) +
                                                  " out of range (" + std::to_string(v.size()) +
                                                  " vertices so far)");
                }
                corners.push_back({vr, ni});
            }
            for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
                triangles.push_back({corners[0], corners[k], corners[k + 1]});
                triangle_line.push_back(at);
            }
        } else if (key != "vt" && key != "o" && key != "g" && key != "s" && key != "usemtl" &&
                   key != "mtllib") {
            return import::line_error(path, at, "unknown statement '" + std::string(key) + "'");
        }
    }
    if (triangles.empty()) return import::file_error(path, "no faces in the file");

    // Corners without a normal share an area-weighted average of their faces' normals.
    std::vector<glm::dvec3> smooth(v.size(), glm::dvec3(0.0));
    for (const auto& tri : triangles) {
        const glm::dvec3 g = glm::cross(v[tri[1].v] - v[tri[0].v], v[tri[2].v] - v[tri[0].v]);
        for (const Corner& c : tri) smooth[c.v] += g;
    }
    MetalMesh mesh;
    mesh.f0 = metal_f0(metal);
    mesh.roughness = static_cast<float>(roughness);
    std::map<std::pair<long long, long long>, std::uint32_t> made;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        for (const Corner& c : triangles[i]) {
            auto [it, fresh] = made.try_emplace({c.v, c.n}, std::uint32_t(mesh.positions.size()));
            if (fresh) {
                const glm::dvec3 n = c.n >= 0 ? vn[c.n] : smooth[c.v];
                if (!(glm::length(n) > 0.0)) {
                    return import::line_error(
                        path, triangle_line[i],
                        "a vertex has no normal (zero vn, or only faces without area)");
                }
                mesh.positions.emplace_back(v[c.v]);
                mesh.normals.emplace_back(glm::normalize(n));
            }
            mesh.indices.push_back(it->second);
        }
    }
    return mesh;
}

}  // namespace gem
