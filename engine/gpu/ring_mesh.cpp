#include "gpu/ring_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "piece/stone_shape.hpp"

namespace gem::gpu {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Air between the stone and the metal where they should not touch (mm).
constexpr double kClearanceMm = 0.15;

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

Result<MetalMesh> make_ring(const RingParams& params, const Stone& stone) {
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

    MetalMesh mesh;
    mesh.f0 = metal_f0(params.metal);
    mesh.roughness = static_cast<float>(params.roughness);
    MeshBuilder b(mesh);

    const double t = params.band_thickness_mm;
    const double shank_top = -(depth + kClearanceMm);
    const glm::dvec3 shank_centre(0.0, shank_top - params.inner_radius_mm - t, 0.0);
    b.torus(shank_centre, {0, 1, 0}, {0, 0, 1}, params.inner_radius_mm + 0.5 * t,
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
        b.cylinder(point(base.x, base.y), joint, 0.5 * w, glm::dvec3(-out.x, 0, -out.z), 8);
        b.cylinder(joint, tip, 0.5 * w, -out, 8);
        b.sphere(joint, 0.5 * w, 8, 12);
        b.sphere(tip, 0.6 * w, 8, 12);
    }
    // A gallery rail joins the prongs under the stone, as in a basket setting.
    b.torus(glm::dvec3(0.0, seat_y, 0.0), {1, 0, 0}, {0, 0, -1}, seat_radius, 0.3 * w,
                      0.3 * w, params.segments, 8);
    return mesh;
}

}  // namespace gem::gpu
