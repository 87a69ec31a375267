// The brilliant facet pattern on a convex girdle outline.
//
// Round (girdle radius R, main azimuths φ_k = k·45°), with g the girdle thickness:
//  - bezel k tilts crown_angle from horizontal and passes through the girdle point at φ_k,
//    y = +g/2; pavilion main k tilts pavilion_angle through the same point at y = −g/2.
//  - The table corners lie on the bezels' centre lines at radius table_pct·W/2, i.e. table_pct
//    is the table's width across corners; the table plane is at their height.
//  - Star k passes through table corners k and k+1 and the star tip on the line where bezels
//    k and k+1 meet, at horizontal distance m + star_pct·(R − m) from the axis, m being the
//    table edge's midpoint distance. (On fancy outlines: star_pct of the way from the table
//    edge's midpoint toward the girdle point half way between the mains.)
//  - Upper girdles join the star tip to the girdle points at φ_k, φ_k + 22.5° and φ_k + 45°;
//    lower girdles join the girdle points at y = −g/2 to the point where mains k and k+1 meet
//    at R·(1 − lower_girdle_pct/100) from the axis.
//  - A culet (culet_pct > 0) is the horizontal plane where the mains' octagon is that wide
//    across flats.
// On a fancy outline the same points are taken on the outline (mains at t = k·45°) and each
// plane's horizontal normal follows the outline normal at its girdle point. The table's and
// culet's heights come from the nominal angles across the width (the short axis), so crown and
// pavilion angles vary around a fancy stone as they do on real ones. A princess takes its table
// corners from a rounded square: on its own square the corners at the side middles would lie on
// the table's edges and the stars would coincide with the bezels.

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/cuts/cut_internal.hpp"

namespace gem::cuts {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec3 lift(const glm::dvec2& q, double y) {
    return {q.x, y, q.y};
}

// The point X on the line where two planes meet with (X − from)·u = along, X and `from`
// taken horizontally and u a horizontal unit vector. On a round stone u points away from the
// axis, so this is the point at a given horizontal distance; on fancy outlines it keeps the
// round's proportions along the facet's own direction and always has a solution.
glm::dvec3 point_along(const Plane& a, const Plane& b, const glm::dvec2& from, const glm::dvec2& u,
                       double along) {
    const glm::dvec3 dir = glm::cross(a.n, b.n);
    const double nn = glm::dot(a.n, b.n);
    const double det = 1.0 - nn * nn;
    const glm::dvec3 p0 = ((a.d - b.d * nn) * a.n + (b.d - a.d * nn) * b.n) / det;
    const double rate = glm::dot(glm::dvec2(dir.x, dir.z), u);
    assert(std::abs(rate) > 1e-12);
    const double t = (along - glm::dot(glm::dvec2(p0.x, p0.z) - from, u)) / rate;
    return p0 + t * dir;
}

// Keeps a point of a facet-meeting line between 2 % and 98 % of the way from height y0 to y1
// (table to girdle, culet to girdle), so that a star or lower-girdle tip never leaves its
// crown or pavilion on a stretched fancy outline. Within the parameter ranges the round never
// needs it: its tightest case, table 70 % with stars 35 %, puts the star tips 3.9 % down.
glm::dvec3 keep_between(const glm::dvec3& p, const Plane& a, const Plane& b, double y0, double y1) {
    const glm::dvec3 dir = glm::cross(a.n, b.n);
    const double q = std::clamp((p.y - y0) / (y1 - y0), 0.02, 0.98);
    return p + ((y0 + q * (y1 - y0)) - p.y) / dir.y * dir;
}

}  // namespace

std::vector<FacetPlane> brilliant_planes(const Outline& outline, int girdle_samples,
                                         const CutParams& params, const Outline* table_outline) {
    assert(girdle_samples % 16 == 0);
    const double w = params.width_mm;
    const BrilliantLevels levels = brilliant_levels(params);
    const double g = levels.girdle;
    const double table = params.table_pct / 100.0;
    const double tan_pavilion = std::tan(params.pavilion_angle_deg * kPi / 180.0);
    const double table_y = levels.table_y;
    const glm::dvec3 culet(0.0, levels.culet_y, 0.0);
    const glm::dvec3 inside(0.0);

    std::vector<OutlinePoint> ring;
    for (int j = 0; j < girdle_samples; ++j)
        ring.push_back(outline(2.0 * kPi * j / girdle_samples));
    const int step = girdle_samples / 8;
    auto main_point = [&](int k) { return ring[std::size_t((k % 8) * step)]; };
    auto gap_point = [&](int k) { return ring[std::size_t((k % 8) * step + step / 2)]; };

    std::array<Plane, 8> bezel, pavilion_main;
    std::array<glm::dvec3, 8> corner;
    for (int k = 0; k < 8; ++k) {
        const OutlinePoint m = main_point(k);
        const glm::dvec2 t = table_outline ? (*table_outline)(2.0 * kPi * k / 8.0).p : m.p;
        corner[k] = lift(table * t, table_y);
        bezel[k] = tilted_plane(lift(m.p, g / 2.0), corner[k], m.n, 1.0);
        pavilion_main[k] = tilted_plane(lift(m.p, -g / 2.0), culet, m.n, -1.0);
    }

    std::vector<FacetPlane> planes{{Plane{{0.0, 1.0, 0.0}, table_y}, FacetKind::table, "table"}};
    std::vector<FacetPlane> crown, pavilion;
    for (int k = 0; k < 8; ++k) {
        const int next = (k + 1) % 8;
        const glm::dvec3 gk = lift(main_point(k).p, g / 2.0);
        const glm::dvec3 gm = lift(gap_point(k).p, g / 2.0);
        const glm::dvec3 gn = lift(main_point(next).p, g / 2.0);
        const glm::dvec3 mid3 = (corner[k] + corner[next]) / 2.0;
        const glm::dvec2 edge_mid(mid3.x, mid3.z);
        const glm::dvec2 to_gap = gap_point(k).p - edge_mid;
        const glm::dvec3 star_tip =
            keep_between(point_along(bezel[k], bezel[next], edge_mid, glm::normalize(to_gap),
                                     params.star_pct / 100.0 * glm::length(to_gap)),
                         bezel[k], bezel[next], table_y, g / 2.0);
        planes.push_back(
            {plane_through(corner[k], corner[next], star_tip, inside), FacetKind::crown, "star"});
        crown.push_back({bezel[k], FacetKind::crown, "bezel"});
        crown.push_back(
            {plane_through(star_tip, gk, gm, inside), FacetKind::crown, "upper girdle"});
        crown.push_back(
            {plane_through(star_tip, gm, gn, inside), FacetKind::crown, "upper girdle"});

        const glm::dvec3 lk = gk - glm::dvec3(0.0, g, 0.0);
        const glm::dvec3 lm = gm - glm::dvec3(0.0, g, 0.0);
        const glm::dvec3 ln = gn - glm::dvec3(0.0, g, 0.0);
        const glm::dvec2 gap = gap_point(k).p;
        const glm::dvec3 lower_tip = keep_between(
            point_along(pavilion_main[k], pavilion_main[next], glm::dvec2(0.0), glm::normalize(gap),
                        (1.0 - params.lower_girdle_pct / 100.0) * glm::length(gap)),
            pavilion_main[k], pavilion_main[next], culet.y, -g / 2.0);
        pavilion.push_back({pavilion_main[k], FacetKind::pavilion, "pavilion main"});
        pavilion.push_back(
            {plane_through(lower_tip, lk, lm, inside), FacetKind::pavilion, "lower girdle"});
        pavilion.push_back(
            {plane_through(lower_tip, lm, ln, inside), FacetKind::pavilion, "lower girdle"});
    }
    planes.insert(planes.end(), crown.begin(), crown.end());
    planes.insert(planes.end(), pavilion.begin(), pavilion.end());
    if (params.culet_pct > 0.0) {
        const double culet_y = culet.y + params.culet_pct / 100.0 * (w / 2.0) * tan_pavilion;
        planes.push_back({Plane{{0.0, -1.0, 0.0}, -culet_y}, FacetKind::culet, "culet"});
    }
    const std::vector<FacetPlane> girdle = girdle_planes(ring);
    planes.insert(planes.end(), girdle.begin(), girdle.end());
    return planes;
}

BrilliantLevels brilliant_levels(const CutParams& params) {
    const double w = params.width_mm;
    const double g = params.girdle_pct / 100.0 * w;
    const double tan_crown = std::tan(params.crown_angle_deg * kPi / 180.0);
    const double tan_pavilion = std::tan(params.pavilion_angle_deg * kPi / 180.0);
    return {g, g / 2.0 + (1.0 - params.table_pct / 100.0) * (w / 2.0) * tan_crown,
            -g / 2.0 - (w / 2.0) * tan_pavilion};
}

Plane tilted_plane(const glm::dvec3& g, const glm::dvec3& apex, const glm::dvec2& n, double up) {
    const double rise = std::abs(apex.y - g.y);
    const double run = glm::dot(n, glm::dvec2(g.x - apex.x, g.z - apex.z));
    const glm::dvec3 normal = glm::normalize(glm::dvec3(rise * n.x, up * run, rise * n.y));
    return {normal, glm::dot(normal, g)};
}

std::vector<FacetPlane> girdle_planes(const std::vector<OutlinePoint>& polygon) {
    std::vector<FacetPlane> planes;
    for (std::size_t j = 0; j < polygon.size(); ++j) {
        const glm::dvec2 a = polygon[j].p;
        const glm::dvec2 e = polygon[(j + 1) % polygon.size()].p - a;
        const glm::dvec3 n = glm::normalize(glm::dvec3(e.y, 0.0, -e.x));  // counter-clockwise
        const Plane plane{n, glm::dot(n, lift(a, 0.0))};
        if (!planes.empty() && glm::length(planes.back().plane.n - n) < 1e-12) continue;
        planes.push_back({plane, FacetKind::girdle, "girdle"});
    }
    while (planes.size() > 1 &&
           glm::length(planes.back().plane.n - planes.front().plane.n) < 1e-12) {
        planes.pop_back();
    }
    return planes;
}

Plane plane_through(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                    const glm::dvec3& inside) {
    glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
    if (glm::dot(n, inside - a) > 0.0) n = -n;
    return {n, glm::dot(n, a)};
}

}  // namespace gem::cuts
