// The heart: non-convex, so it is glued from two convex halves. Each half is the brilliant
// pattern on the convex hull of the two lobes and the tip, cut by the mirror plane x = 0 and
// by the cleft: a short vertical girdle wall from the cleft's apex up to the lobe, with a
// crown and a pavilion facet sloping into it. The halves are mirrored across x = 0, their
// mirror facets dropped and the rest glued by stone_from_triangles, which merges the facets
// that cross the mirror (table, the tip's mains, ...) and finds the stone non-convex.

#include <cmath>

#include "geometry/cuts/cut_internal.hpp"

namespace gem::cuts {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLobeRadius = 0.28;  // of the width
constexpr double kCleftDepth = 0.12;  // apex below the lobes' tops, of the width
// The cleft's wall meets the lobe's circle at this angle about the lobe's centre.
constexpr double kCleftMeetsLobe = 100.0 * kPi / 180.0;
// The sides leave the lobes this far above the tangent from the tip and bulge toward it as
// circular arcs: straight sides would make the bezels there contain whole girdle edges, so the
// upper girdles beside them would vanish (as on a princess with straight sides).
constexpr double kSideBulge = 15.0 * kPi / 180.0;

struct Lobes {
    double radius;
    glm::dvec2 centre;  // of the right lobe
    glm::dvec2 tip;
    double side_start;       // angle about the centre where the right side leaves the lobe
    glm::dvec2 side_centre;  // of the side's arc, tangent to the lobe there
    double side_radius;
    double tip_angle;  // of the tip about side_centre
};

Lobes lobes(double length, double width) {
    Lobes l;
    l.radius = kLobeRadius * width;
    l.centre = {width / 2.0 - l.radius, length / 2.0 - l.radius};
    l.tip = {0.0, -length / 2.0};
    const glm::dvec2 v = l.tip - l.centre;
    l.side_start = std::atan2(v.y, v.x) + std::acos(l.radius / glm::length(v)) + kSideBulge;
    const glm::dvec2 n(std::cos(l.side_start), std::sin(l.side_start));
    const glm::dvec2 start = l.centre + l.radius * n;
    // The arc's centre start − R·n is as far from the tip as from start.
    const glm::dvec2 to_tip = l.tip - start;
    l.side_radius = -glm::dot(to_tip, to_tip) / (2.0 * glm::dot(n, to_tip));
    l.side_centre = start - l.side_radius * n;
    l.tip_angle = std::atan2(l.tip.y - l.side_centre.y, l.tip.x - l.side_centre.x);
    return l;
}

// Where the ray from `from` along unit u leaves a circle (`from` being inside).
glm::dvec2 ray_exit(const glm::dvec2& from, const glm::dvec2& u, const glm::dvec2& centre,
                    double radius) {
    const glm::dvec2 c = centre - from;
    const double uc = glm::dot(u, c);
    const double disc = uc * uc - glm::dot(c, c) + radius * radius;
    return from + (uc + std::sqrt(std::max(0.0, disc))) * u;
}

double angle_about(const glm::dvec2& q, const glm::dvec2& centre) {
    return std::atan2(q.y - centre.y, q.x - centre.x);
}

// Where the ray along u (u.x >= 0) leaves the hull's right half: the lobe's arc, the side's
// arc down to the tip or the straight top between the lobes. Rays start on the axis level with
// the lobes' centres, so that t = 0 is the widest point and the width comes out exact.
OutlinePoint right_half(const Lobes& l, const glm::dvec2& u) {
    if (u.x < 1e-12 && u.y < 0.0) return {l.tip, {0.0, -1.0}};
    const glm::dvec2 from(0.0, l.centre.y);
    if (u.y > 0.0 && u.x / u.y * l.radius <= l.centre.x) {
        return {from + u * (l.radius / u.y), {0.0, 1.0}};
    }
    const glm::dvec2 q = ray_exit(from, u, l.centre, l.radius);
    if (angle_about(q, l.centre) >= l.side_start) return {q, (q - l.centre) / l.radius};
    const glm::dvec2 r = ray_exit(from, u, l.side_centre, l.side_radius);
    return {r, (r - l.side_centre) / l.side_radius};
}

Outline hull_outline(const Lobes& l) {
    return [l](double t) {
        const glm::dvec2 u(std::cos(t), std::sin(t));
        if (u.x >= 0.0) return right_half(l, u);
        OutlinePoint q = right_half(l, {-u.x, u.y});
        q.p.x = -q.p.x;
        q.n.x = -q.n.x;
        return q;
    };
}

glm::dvec3 lift(const glm::dvec2& q, double y) {
    return {q.x, y, q.y};
}

std::vector<FacetPlane> cleft_planes(const Lobes& l, const CutParams& params, double width) {
    const BrilliantLevels levels = brilliant_levels(params);
    const glm::dvec2 apex(0.0, l.centre.y + l.radius - kCleftDepth * width);
    const glm::dvec2 meet =
        l.centre + l.radius * glm::dvec2(std::cos(kCleftMeetsLobe), std::sin(kCleftMeetsLobe));
    const glm::dvec2 e = meet - apex;
    const glm::dvec2 m = glm::normalize(glm::dvec2(-e.y, e.x));  // out of the stone, up and left
    const double table = params.table_pct / 100.0;
    const double g = levels.girdle;
    return {
        {Plane{lift(m, 0.0), glm::dot(m, apex)}, FacetKind::girdle, "cleft girdle"},
        {tilted_plane(lift(apex, g / 2.0), lift(table * apex, levels.table_y), m, 1.0),
         FacetKind::crown, "cleft bezel"},
        {tilted_plane(lift(apex, -g / 2.0), glm::dvec3(0.0, levels.culet_y, 0.0), m, -1.0),
         FacetKind::pavilion, "cleft main"},
    };
}

bool same_plane(const Plane& a, const Plane& b, double tolerance) {
    return glm::length(a.n - b.n) < 1e-6 && std::abs(a.d - b.d) < tolerance;
}

}  // namespace

Result<Stone> make_heart(const CutParams& params) {
    const double w = params.width_mm;
    const Lobes l = lobes(params.length_to_width * w, w);
    std::vector<FacetPlane> planes =
        brilliant_planes(hull_outline(l), params.faceted_girdle ? 32 : 128, params);
    const std::vector<FacetPlane> cleft = cleft_planes(l, params, w);
    planes.insert(planes.end(), cleft.begin(), cleft.end());
    planes.push_back({Plane{{-1.0, 0.0, 0.0}, 0.0}, FacetKind::other, "mirror"});
    auto kept = planes_that_make_facets(planes);
    if (!kept) return Error{"half heart: " + kept.error()};
    auto half = stone_from_planes(kept.value(), "half heart");
    if (!half) return half;

    // Glue: the half without its mirror facet, and its mirror image wound the other way.
    const Stone& h = half.value();
    const glm::dvec3 flip(-1.0, 1.0, 1.0);
    const auto n = std::uint32_t(h.vertices.size());
    std::vector<glm::dvec3> positions = h.vertices;
    for (const glm::dvec3& v : h.vertices) positions.push_back(v * flip);
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (const MeshTriangle& t : h.triangles) {
        if (h.facets[t.facet].name == "mirror") continue;
        triangles.push_back(t.v);
        triangles.push_back({t.v[0] + n, t.v[2] + n, t.v[1] + n});
    }
    auto heart = stone_from_triangles(positions, triangles, "heart");
    if (!heart) return Error{"gluing the heart's halves: " + heart.error()};

    // The glued facets come back unnamed: take kind and name from the plane they lie in.
    const double tolerance = 1e-6 * w;
    for (Facet& facet : heart.value().facets) {
        for (const Facet& source : h.facets) {
            const Plane mirrored{source.plane.n * flip, source.plane.d};
            if (same_plane(facet.plane, source.plane, tolerance) ||
                same_plane(facet.plane, mirrored, tolerance)) {
                facet.kind = source.kind;
                facet.name = source.name;
                break;
            }
        }
    }
    // Turn the tip toward +z: face-up, the camera's image has −z at the top, and jewellers
    // show a heart with its lobes up and its point down. A half turn about y keeps winding.
    Stone& stone = heart.value();
    for (glm::dvec3& v : stone.vertices) v = {-v.x, v.y, -v.z};
    for (Facet& facet : stone.facets) {
        facet.plane.n = {-facet.plane.n.x, facet.plane.n.y, -facet.plane.n.z};
    }
    return heart;
}

}  // namespace gem::cuts
