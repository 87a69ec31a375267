#include "gpu/ring_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "import/import_text.hpp"

namespace gem::gpu {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Air between the stone and the metal where they should not touch (mm).
constexpr double kClearanceMm = 0.15;

// Closed pieces are added one by one; each may overlap the others (a jeweller's solder joint
// needs no boolean union to look right, and each piece stays a closed surface).
class MeshBuilder {
  public:
    explicit MeshBuilder(RingMesh& mesh) : mesh_(mesh) {}

    std::uint32_t vertex(const glm::dvec3& p, const glm::dvec3& n) {
        mesh_.positions.emplace_back(p);
        mesh_.normals.emplace_back(glm::normalize(n));
        return static_cast<std::uint32_t>(mesh_.positions.size() - 1);
    }
    // Wound so that the face's geometric normal agrees with its vertices' analytic normals:
    // the generators below then need not track orientation through their parametrisations.
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const glm::vec3 g = glm::cross(mesh_.positions[b] - mesh_.positions[a],
                                       mesh_.positions[c] - mesh_.positions[a]);
        const glm::vec3 n = mesh_.normals[a] + mesh_.normals[b] + mesh_.normals[c];
        if (glm::dot(g, n) < 0.0f) std::swap(b, c);
        mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
    }
    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }

  private:
    RingMesh& mesh_;
};

// A tube of elliptic cross-section swept around a circle: centre `c`, the circle in the plane
// spanned by e0 and e1, cross-section semi-axes `radial` (in the circle's plane) and `axial`
// (along e0 × e1) about the circle of radius `r`.
void add_swept_ellipse(MeshBuilder& b, const glm::dvec3& c, const glm::dvec3& e0,
                       const glm::dvec3& e1, double r, double radial, double axial, int segments,
                       int profile) {
    const glm::dvec3 axis = glm::cross(e0, e1);
    std::vector<std::uint32_t> ids;
    for (int i = 0; i < segments; ++i) {
        const double phi = 2.0 * kPi * i / segments;
        const glm::dvec3 out = std::cos(phi) * e0 + std::sin(phi) * e1;
        for (int j = 0; j < profile; ++j) {
            const double theta = 2.0 * kPi * j / profile;
            const glm::dvec3 p =
                c + (r + radial * std::cos(theta)) * out + axial * std::sin(theta) * axis;
            // The ellipse's normal: the gradient of (u/a)² + (v/b)².
            const glm::dvec3 n = std::cos(theta) / radial * out + std::sin(theta) / axial * axis;
            ids.push_back(b.vertex(p, n));
        }
    }
    auto at = [&](int i, int j) {
        return ids[static_cast<std::size_t>((i % segments) * profile + (j % profile))];
    };
    for (int i = 0; i < segments; ++i) {
        for (int j = 0; j < profile; ++j)
            b.quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

// A closed cylinder of `sides` from a to b; `e1` is perpendicular to the axis and fixes where
// the first side vertex lies (a vertex at -e1 is exactly `radius` from the axis that way).
void add_cylinder(MeshBuilder& b, const glm::dvec3& a, const glm::dvec3& c, double radius,
                  const glm::dvec3& e1, int sides) {
    const glm::dvec3 axis = glm::normalize(c - a);
    const glm::dvec3 u = glm::normalize(e1 - glm::dot(e1, axis) * axis);
    const glm::dvec3 v = glm::cross(axis, u);
    std::vector<std::uint32_t> side_a, side_c, cap_a, cap_c;
    for (int j = 0; j < sides; ++j) {
        const double theta = 2.0 * kPi * j / sides;
        const glm::dvec3 radial = std::cos(theta) * u + std::sin(theta) * v;
        side_a.push_back(b.vertex(a + radius * radial, radial));
        side_c.push_back(b.vertex(c + radius * radial, radial));
        cap_a.push_back(b.vertex(a + radius * radial, -axis));
        cap_c.push_back(b.vertex(c + radius * radial, axis));
    }
    const std::uint32_t centre_a = b.vertex(a, -axis);
    const std::uint32_t centre_c = b.vertex(c, axis);
    for (int j = 0; j < sides; ++j) {
        const int k = (j + 1) % sides;
        b.quad(side_a[j], side_a[k], side_c[k], side_c[j]);
        b.triangle(centre_a, cap_a[k], cap_a[j]);
        b.triangle(centre_c, cap_c[j], cap_c[k]);
    }
}

void add_sphere(MeshBuilder& b, const glm::dvec3& c, double radius, int rings, int sides) {
    const std::uint32_t south = b.vertex(c - glm::dvec3(0, radius, 0), {0, -1, 0});
    const std::uint32_t north = b.vertex(c + glm::dvec3(0, radius, 0), {0, 1, 0});
    std::vector<std::uint32_t> ids;
    for (int i = 1; i < rings; ++i) {
        const double lat = -0.5 * kPi + kPi * i / rings;
        for (int j = 0; j < sides; ++j) {
            const double lon = 2.0 * kPi * j / sides;
            const glm::dvec3 n(std::cos(lat) * std::cos(lon), std::sin(lat),
                               std::cos(lat) * std::sin(lon));
            ids.push_back(b.vertex(c + radius * n, n));
        }
    }
    auto at = [&](int i, int j) { return ids[static_cast<std::size_t>(i * sides + j % sides)]; };
    for (int j = 0; j < sides; ++j) {
        b.triangle(south, at(0, j), at(0, j + 1));
        b.triangle(north, at(rings - 2, j + 1), at(rings - 2, j));
        for (int i = 0; i + 1 < rings - 1; ++i)
            b.quad(at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
    }
}

// Möller & Trumbore (1997): distance along d from o to the triangle, or -1.
double ray_triangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a,
                    const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, q = glm::cross(d, e2);
    const double det = glm::dot(e1, q);
    if (std::abs(det) < 1e-15) return -1.0;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, q) / det;
    if (u < 0.0 || u > 1.0) return -1.0;
    const glm::dvec3 r = glm::cross(s, e1);
    const double v = glm::dot(d, r) / det;
    if (v < 0.0 || u + v > 1.0) return -1.0;
    return glm::dot(e2, r) / det;
}

// How far the stone reaches from its centre along horizontal direction `u`: the farthest
// crossing of the ray with its surface, so non-convex outlines (a heart's cleft) count too.
double outline_radius(const Stone& stone, const glm::dvec3& u) {
    double far = 0.0;
    for (const MeshTriangle& t : stone.triangles) {
        far = std::max(far, ray_triangle(glm::dvec3(0.0), u, stone.vertices[t.v[0]],
                                         stone.vertices[t.v[1]], stone.vertices[t.v[2]]));
    }
    return far;
}

Result<bool> check(const RingParams& p) {
    auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    if (!positive(p.inner_radius_mm)) return Error{"ring.inner_radius_mm: must be positive"};
    if (!positive(p.band_width_mm)) return Error{"ring.band_width_mm: must be positive"};
    if (!positive(p.band_thickness_mm)) return Error{"ring.band_thickness_mm: must be positive"};
    if (!positive(p.prong_width_mm)) return Error{"ring.prong_width_mm: must be positive"};
    if (p.prongs < 0 || p.prongs > 16) return Error{"ring.prongs: must be 0..16"};
    if (!(p.roughness >= 0.0 && p.roughness <= 1.0)) return Error{"ring.roughness: must be 0..1"};
    if (p.segments < 8 || p.segments > 1024) return Error{"ring.segments: must be 8..1024"};
    return true;
}

}  // namespace

double RingMesh::radius_mm() const {
    double r2 = 0.0;
    for (const glm::vec3& p : positions) r2 = std::max(r2, double(glm::dot(p, p)));
    return std::sqrt(r2);
}

glm::vec3 metal_f0(RingParams::Metal metal) {
    // Measured sRGB colours from Filament's material guide ("Physically Based Rendering in
    // Filament", Guy & Agopian, table "metallic base colors"), decoded to linear here:
    // gold (255, 220, 157), silver (250, 249, 245), platinum (214, 209, 200). White gold is
    // a gold-palladium alloy: palladium's linear F0 from Adobe's Standard Material metal
    // references (Pd, 0.7363, 0.7023, 0.6602).
    switch (metal) {
        case RingParams::Metal::yellow_gold:
            return {1.000f, 0.716f, 0.337f};
        case RingParams::Metal::white_gold:
            return {0.736f, 0.702f, 0.660f};
        case RingParams::Metal::platinum:
            return {0.672f, 0.638f, 0.578f};
        case RingParams::Metal::silver:
            return {0.956f, 0.947f, 0.913f};
    }
    return glm::vec3(1.0f);
}

Result<RingMesh> make_ring(const RingParams& params, const Stone& stone) {
    if (auto ok = check(params); !ok) return Error{ok.error()};
    if (stone.vertices.empty() || stone.triangles.empty()) {
        return Error{"ring: the stone '" + stone.name + "' has no geometry"};
    }
    double depth = 0.0;   // culet below the girdle plane
    double widest = 0.0;  // largest girdle radius
    for (const glm::dvec3& v : stone.vertices) {
        depth = std::max(depth, -v.y);
        widest = std::max(widest, std::hypot(v.x, v.z));
    }
    double girdle_top = 0.0;  // the top of the girdle band, where the crown begins
    for (const glm::dvec3& v : stone.vertices) {
        if (std::hypot(v.x, v.z) > 0.97 * widest) girdle_top = std::max(girdle_top, v.y);
    }

    RingMesh mesh;
    mesh.f0 = metal_f0(params.metal);
    mesh.roughness = static_cast<float>(params.roughness);
    MeshBuilder b(mesh);

    const double t = params.band_thickness_mm;
    const double shank_top = -(depth + kClearanceMm);
    const glm::dvec3 shank_centre(0.0, shank_top - params.inner_radius_mm - t, 0.0);
    add_swept_ellipse(b, shank_centre, {0, 1, 0}, {0, 0, 1}, params.inner_radius_mm + 0.5 * t,
                      0.5 * t, 0.5 * params.band_width_mm, params.segments, 16);
    if (params.prongs == 0) return mesh;

    // Each prong runs parallel to the pavilion, offset so it clears it, from inside the shank
    // up to the girdle, then straight up past the girdle with a ball over the crown's edge.
    const double w = params.prong_width_mm;
    const double base_y = shank_top - 0.25 * t;
    const double seat_y = -0.35 * depth;
    double seat_radius = 0.0;
    for (int k = 0; k < params.prongs; ++k) {
        const double az = 2.0 * kPi * (k + 0.5) / params.prongs;
        const glm::dvec3 out(std::cos(az), 0.0, std::sin(az));
        const double girdle = outline_radius(stone, out);
        if (!(girdle > 0.0)) return Error{"ring: the stone '" + stone.name + "' has no girdle"};
        // In the prong's (r, y) half-plane: the pavilion runs from (girdle, 0) to (0, -depth).
        const glm::dvec2 along = glm::normalize(glm::dvec2(-girdle, -depth));
        const glm::dvec2 outward(-along.y, along.x);  // points away from the stone
        const glm::dvec2 start = glm::dvec2(girdle, 0.0) + (0.5 * w + kClearanceMm) * outward;
        const double centre_r = girdle + 0.5 * w;  // the prong's inner face at the girdle
        // Where the offset line meets r = centre_r (the joint) and y = base_y (the base).
        const double joint_y = start.y + (centre_r - start.x) / along.x * along.y;
        const glm::dvec2 base = start + (base_y - start.y) / along.y * along;
        const glm::dvec2 seat = start + (seat_y - start.y) / along.y * along;
        seat_radius = std::max(seat_radius, seat.x);
        auto point = [&](double r, double y) { return glm::dvec3(r * out.x, y, r * out.z); };
        const glm::dvec3 joint = point(centre_r, std::min(joint_y, 0.0));
        const glm::dvec3 tip = point(centre_r, girdle_top + 0.6 * w);
        add_cylinder(b, point(base.x, base.y), joint, 0.5 * w, glm::dvec3(-out.x, 0, -out.z), 8);
        add_cylinder(b, joint, tip, 0.5 * w, -out, 8);
        add_sphere(b, joint, 0.5 * w, 8, 12);
        add_sphere(b, tip, 0.6 * w, 8, 12);
    }
    // A gallery rail joins the prongs under the stone, as in a basket setting.
    add_swept_ellipse(b, glm::dvec3(0.0, seat_y, 0.0), {1, 0, 0}, {0, 0, -1}, seat_radius, 0.3 * w,
                      0.3 * w, params.segments, 8);
    return mesh;
}

Result<RingMesh> load_ring_obj(const std::filesystem::path& path, RingParams::Metal metal,
                               double roughness) {
    if (!(roughness >= 0.0 && roughness <= 1.0)) {
        return Error{path.string() + ": roughness must be 0..1"};
    }
    auto bytes = import::read_whole_file(path);
    if (!bytes) return Error{bytes.error()};
    std::vector<glm::dvec3> v;
    std::vector<glm::dvec3> vn;
    struct Corner {
        long long v, n;  // 0-based; n = -1 without a normal
    };
    std::vector<std::array<Corner, 3>> triangles;
    std::vector<std::size_t> triangle_line;
    import::LineCursor cursor(bytes.value());
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
    RingMesh mesh;
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

}  // namespace gem::gpu
