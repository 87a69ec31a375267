#include "trace/folded_exit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gem {
namespace {

glm::dvec2 xz(const glm::dvec3& v) {
    return {v.x, v.z};
}

glm::dvec2 reflect_across(glm::dvec2 v, glm::dvec2 m) {
    return v - 2.0 * glm::dot(v, m) * m;
}

// The mirror line at angle beta (radians from +x toward +z): its normal toward larger angles.
glm::dvec2 mirror_normal(double beta) {
    return {-std::sin(beta), std::cos(beta)};
}

// True when the polygon's outline seen along y reaches inside the wedge of angles [0, beta]
// (beta below pi): the part of it the wedge's two half-planes keep has its centre farther
// than `tolerance` mm inside both. A facet that only touches the wedge's edges (a mirror
// line, or the axis: a pavilion main at the culet) does not count: where it touches, its
// mirror image across that line touches too, from inside, and a point on a mirror line lies
// outside a facet's plane exactly when it lies outside its image's.
bool reaches_inside(const std::vector<glm::dvec2>& polygon, double beta, double tolerance) {
    const std::array<glm::dvec2, 2> inward = {glm::dvec2(0.0, 1.0),
                                              glm::dvec2(std::sin(beta), -std::cos(beta))};
    std::vector<glm::dvec2> kept = polygon;
    for (const glm::dvec2& e : inward) {
        std::vector<glm::dvec2> next;
        for (std::size_t i = 0; i < kept.size(); ++i) {
            const glm::dvec2 a = kept[i];
            const glm::dvec2 b = kept[(i + 1) % kept.size()];
            const double da = glm::dot(e, a);
            const double db = glm::dot(e, b);
            if (da >= 0.0) next.push_back(a);
            if ((da >= 0.0) != (db >= 0.0)) next.push_back(a + (b - a) * (da / (da - db)));
        }
        kept = std::move(next);
        if (kept.empty()) return false;
    }
    glm::dvec2 centre(0.0);
    for (const glm::dvec2& k : kept) centre += k;
    centre /= static_cast<double>(kept.size());
    return glm::dot(inward[0], centre) > tolerance && glm::dot(inward[1], centre) > tolerance;
}

// The stone turned about its axis (TurnedOutline), from its corners; the stone is mirrored by
// x = 0 and z = 0, so its bounding box is centred on the axis.
TurnedOutline turned_outline(const std::vector<glm::dvec3>& corners, const glm::dvec3& low,
                             const glm::dvec3& high) {
    TurnedOutline s;
    s.z_scale = (high.x - low.x) / std::max(high.z - low.z, 1e-12);
    s.y_min = low.y;
    s.y_max = high.y;
    auto radius_of = [&](const glm::dvec3& v) { return std::hypot(v.x, v.z * s.z_scale); };
    s.radius = 1e-12;
    for (const glm::dvec3& v : corners) s.radius = std::max(s.radius, radius_of(v));
    // The girdle: the corners within 2 % of the widest; the table: the topmost corners.
    double girdle_low = high.y;
    double girdle_high = low.y;
    double table = 0.0;
    for (const glm::dvec3& v : corners) {
        const double r = radius_of(v);
        if (r >= 0.98 * s.radius) {
            girdle_low = std::min(girdle_low, v.y);
            girdle_high = std::max(girdle_high, v.y);
        }
        if (v.y >= high.y - 1e-9 * s.radius) table = std::max(table, r);
    }
    if (girdle_low - low.y > 1e-9 * s.radius) s.pavilion_slope = s.radius / (girdle_low - low.y);
    if (high.y - girdle_high > 1e-9 * s.radius && table < s.radius) {
        s.crown_slope = (s.radius - table) / (high.y - girdle_high);
        s.crown_apex = girdle_high + s.radius / s.crown_slope;
    }
    return s;
}

// Where the ray from o along d (z already scaled) leaves the cone r <= k side (y - apex_y),
// side +1 opening upward, -1 downward: the least t > 0 at which it crosses the cone's own
// nappe outward; infinity if it never does, or if k is 0 (no cone).
double leave_cone(const glm::dvec3& o, const glm::dvec3& d, double k, double apex_y, double side) {
    constexpr double kNever = std::numeric_limits<double>::infinity();
    if (k <= 0.0) return kNever;
    const double k2 = k * k;
    const double a = d.x * d.x + d.z * d.z - k2 * d.y * d.y;
    const double b = o.x * d.x + o.z * d.z - k2 * (o.y - apex_y) * d.y;
    const double c = o.x * o.x + o.z * o.z - k2 * (o.y - apex_y) * (o.y - apex_y);
    const double root = std::sqrt(std::max(b * b - a * c, 0.0));
    double best = kNever;
    for (double t : {(-b - root) / a, (-b + root) / a}) {
        if (!(t > 0.0) || t >= best) continue;
        const glm::dvec3 p = o + t * d;
        const double outward = p.x * d.x + p.z * d.z - k2 * (p.y - apex_y) * d.y;
        if (side * (p.y - apex_y) >= 0.0 && outward > 0.0) best = t;
    }
    return best;
}

}  // namespace

std::optional<FoldedExit> FoldedExit::make(const Stone& stone) {
    if (!stone.convex || stone.facets.empty()) return std::nullopt;
    FoldedExit f;
    for (const Facet& facet : stone.facets) f.planes_.push_back(facet.plane);
    double radius = 1e-9;
    glm::dvec3 bounds_min(std::numeric_limits<double>::infinity());
    glm::dvec3 bounds_max = -bounds_min;
    for (const glm::dvec3& v : stone.vertices) {
        radius = std::max(radius, glm::length(v));
        bounds_min = glm::min(bounds_min, v);
        bounds_max = glm::max(bounds_max, v);
    }
    // Planes of one mirror-symmetric stone match to rounding of their construction.
    const double tolerance = 1e-7 * radius;
    auto find_plane = [&](const glm::dvec3& n, double d) -> std::uint32_t {
        for (std::uint32_t i = 0; i < f.planes_.size(); ++i) {
            const Plane& p = f.planes_[i];
            if (std::abs(p.d - d) <= tolerance && glm::length(p.n - n) <= 1e-7) return i;
        }
        return kNoFacet;
    };
    auto mirrored_onto_itself = [&](auto&& mirror) {
        return std::all_of(f.planes_.begin(), f.planes_.end(), [&](const Plane& p) {
            return find_plane(mirror(p.n), p.d) != kNoFacet;
        });
    };
    if (!mirrored_onto_itself([](glm::dvec3 n) { return glm::dvec3(-n.x, n.y, n.z); }) ||
        !mirrored_onto_itself([](glm::dvec3 n) { return glm::dvec3(n.x, n.y, -n.z); })) {
        return std::nullopt;
    }
    double wedge = std::numbers::pi / 2.0;
    for (int level = 0; level < kMaxLevels; ++level) {
        const glm::dvec2 m = mirror_normal(wedge / 2.0);
        const bool holds = mirrored_onto_itself([&](glm::dvec3 n) {
            const glm::dvec2 r = reflect_across(xz(n), m);
            return glm::dvec3(r.x, n.y, r.y);
        });
        if (!holds) break;
        f.mirrors_.push_back(m);
        wedge /= 2.0;
        ++f.levels_;
    }
    for (std::uint32_t i = 0; i < stone.facets.size(); ++i) {
        std::vector<glm::dvec2> outline;
        for (std::uint32_t v : stone.facets[i].loop) outline.push_back(xz(stone.vertices[v]));
        if (reaches_inside(outline, wedge, 10.0 * tolerance)) f.candidates_.push_back(i);
    }
    f.edges_ = {glm::dvec2(0.0, 1.0), glm::dvec2(std::sin(wedge), -std::cos(wedge))};
    f.inside_ = kInside * radius;
    const auto count = static_cast<std::uint32_t>(f.candidates_.size());
    f.unfolded_facet_.resize(static_cast<std::size_t>(f.wedges()) * count);
    for (std::uint32_t bits = 0; bits < static_cast<std::uint32_t>(f.wedges()); ++bits) {
        for (std::uint32_t c = 0; c < count; ++c) {
            const Plane& p = f.planes_[f.candidates_[c]];
            const std::uint32_t facet = find_plane(f.unfold(p.n, bits), p.d);
            if (facet == kNoFacet) return std::nullopt;  // the checks above make it exist
            f.unfolded_facet_[bits * count + c] = facet;
        }
    }
    f.outline_ = turned_outline(stone.vertices, bounds_min, bounds_max);
    return f;
}

std::uint32_t FoldedExit::fold_bits(glm::dvec2 p) const {
    std::uint32_t bits = (p.x < 0.0 ? 1u : 0u) | (p.y < 0.0 ? 2u : 0u);
    p = glm::abs(p);
    for (int i = 0; i < levels_; ++i) {
        if (glm::dot(p, mirrors_[i]) > 0.0) {
            p = reflect_across(p, mirrors_[i]);
            bits |= 4u << i;
        }
    }
    return bits;
}

glm::dvec3 FoldedExit::fold(glm::dvec3 v, std::uint32_t bits) const {
    glm::dvec2 p((bits & 1u) != 0 ? -v.x : v.x, (bits & 2u) != 0 ? -v.z : v.z);
    for (int i = 0; i < levels_; ++i) {
        if ((bits & (4u << i)) != 0) p = reflect_across(p, mirrors_[i]);
    }
    return {p.x, v.y, p.y};
}

glm::dvec3 FoldedExit::unfold(glm::dvec3 v, std::uint32_t bits) const {
    glm::dvec2 p = xz(v);
    for (int i = levels_ - 1; i >= 0; --i) {
        if ((bits & (4u << i)) != 0) p = reflect_across(p, mirrors_[i]);
    }
    return {(bits & 1u) != 0 ? -p.x : p.x, v.y, (bits & 2u) != 0 ? -p.y : p.y};
}

glm::dvec3 FoldedExit::guess(const glm::dvec3& origin, const glm::dvec3& direction) const {
    const TurnedOutline& s = outline_;
    const glm::dvec3 o(origin.x, origin.y, origin.z * s.z_scale);
    const glm::dvec3 d(direction.x, direction.y, direction.z * s.z_scale);
    double t = std::min(leave_cone(o, d, s.pavilion_slope, s.y_min, 1.0),
                        leave_cone(o, d, s.crown_slope, s.crown_apex, -1.0));
    const double a = d.x * d.x + d.z * d.z;
    const double b = o.x * d.x + o.z * d.z;
    const double c = o.x * o.x + o.z * o.z - s.radius * s.radius;
    if (a > 0.0) t = std::min(t, (-b + std::sqrt(std::max(b * b - a * c, 0.0))) / a);
    if (d.y != 0.0) t = std::min(t, ((d.y > 0.0 ? s.y_max : s.y_min) - o.y) / d.y);
    return origin + t * direction;
}

bool FoldedExit::next_exit(const glm::dvec3& origin, const glm::dvec3& direction, SurfaceHit& hit,
                           FoldCost* cost) const {
    FoldCost local;
    FoldCost& c = cost != nullptr ? *cost : local;
    ++c.searches;
    const auto count = static_cast<std::uint32_t>(candidates_.size());
    glm::dvec3 target = guess(origin, direction);
    std::uint32_t visited = 0;
    double best_t = std::numeric_limits<double>::infinity();
    std::uint32_t best = kNoFacet;
    int rounds = 0;
    for (int round = 0; round < wedges(); ++round) {
        const std::uint32_t bits = fold_bits(xz(target));
        if ((visited >> bits & 1u) != 0) break;  // its wedge was seen: the point is the exit
        visited |= 1u << bits;
        ++rounds;
        const glm::dvec3 o = fold(origin, bits);
        const glm::dvec3 d = fold(direction, bits);
        for (std::uint32_t i = 0; i < count; ++i) {
            const Plane& p = planes_[candidates_[i]];
            const double facing = glm::dot(p.n, d);
            if (facing <= kFacingMin) continue;
            const double t = std::max(p.d - glm::dot(p.n, o), 0.0) / facing;
            if (t < best_t) {
                best_t = t;
                best = unfolded_facet_[bits * count + i];
            }
        }
        c.planes += count;
        if (best == kNoFacet) {
            // Nothing ahead in this wedge: the ray heads for the wedge it points into.
            target = direction;
            continue;
        }
        glm::dvec3 folded = fold(origin + best_t * direction, bits);
        const double lo = glm::dot(edges_[0], xz(folded));
        const double hi = glm::dot(edges_[1], xz(folded));
        if (lo >= inside_ && hi >= inside_) break;
        // Next, the wedge the point lies in; one just inside an edge is pushed across it, so
        // the wedge beyond is tested too.
        for (int e = 0; e < 2; ++e) {
            const double depth = e == 0 ? lo : hi;
            if (depth >= 0.0 && depth < inside_) {
                folded.x -= 2.0 * inside_ * edges_[e].x;
                folded.z -= 2.0 * inside_ * edges_[e].y;
            }
        }
        target = unfold(folded, bits);
    }
    c.rounds += static_cast<std::uint64_t>(rounds);
    c.most_rounds = std::max(c.most_rounds, rounds);
    if (best == kNoFacet) return false;
    hit.t = best_t;
    hit.point = origin + best_t * direction;
    hit.facet = best;
    return true;
}

}  // namespace gem
