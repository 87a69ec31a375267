#include "trace/folded_exit.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

namespace gem {
namespace {

// Candidates are chosen for a wedge wider than the one points are checked against by this
// much (radians): a point a float rounding outside the checked wedge still finds its facet.
constexpr double kSlack = 1e-3;

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

// True when the polygon's outline seen along y meets the wedge of angles [lo, hi] (hi - lo
// below pi) farther than `off_axis` mm from the axis: the polygon clipped by the wedge's two
// half-planes keeps such a point. A facet that meets the wedge only on the axis (a pavilion
// main at the culet) shares that point with facets that do count. (The wedge is already wider
// than the one points are checked against, so the clipping needs no tolerance of its own.)
bool touches_wedge(const std::vector<glm::dvec2>& polygon, double lo, double hi, double off_axis) {
    const std::array<glm::dvec2, 2> inward = {glm::dvec2(-std::sin(lo), std::cos(lo)),
                                              glm::dvec2(std::sin(hi), -std::cos(hi))};
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
    return std::any_of(kept.begin(), kept.end(),
                       [&](const glm::dvec2& p) { return glm::length(p) > off_axis; });
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
    // The facets touching the first wedge widened by `margin` on each side (and kSlack more).
    auto touching = [&](double margin) {
        std::vector<std::uint32_t> found;
        for (std::uint32_t i = 0; i < stone.facets.size(); ++i) {
            std::vector<glm::dvec2> outline;
            for (std::uint32_t v : stone.facets[i].loop) outline.push_back(xz(stone.vertices[v]));
            if (touches_wedge(outline, -margin - kSlack, wedge + margin + kSlack,
                              10.0 * tolerance)) {
                found.push_back(i);
            }
        }
        return found;
    };
    // The widest margin, up to half the wedge, that adds no facet: free rounds saved.
    f.candidates_ = touching(0.0);
    for (int step = 32; step > 0; --step) {
        const double margin = wedge * step / 64.0;
        std::vector<std::uint32_t> found = touching(margin);
        if (found.size() == f.candidates_.size()) {
            f.margin_ = margin;
            f.candidates_ = std::move(found);
            break;
        }
    }
    const double lo = -f.margin_;
    const double hi = wedge + f.margin_;
    f.edges_ = {glm::dvec2(-std::sin(lo), std::cos(lo)), glm::dvec2(std::sin(hi), -std::cos(hi))};
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
    f.centre_y_ = 0.5 * (bounds_min.y + bounds_max.y);
    // The stone is mirrored by x = 0 and z = 0, so its box is centred on the axis.
    f.semi_axes_ = glm::max(0.5 * (bounds_max - bounds_min), glm::dvec3(1e-9));
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
    // The ellipsoid scaled to the unit sphere.
    const glm::dvec3 q = (origin - glm::dvec3(0.0, centre_y_, 0.0)) / semi_axes_;
    const glm::dvec3 e = direction / semi_axes_;
    const double a = glm::dot(e, e);
    const double b = glm::dot(q, e);
    const double c = glm::dot(q, q) - 1.0;
    const double s = (-b + std::sqrt(std::max(b * b - a * c, 0.0))) / a;
    return origin + s * direction;
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
        target = origin + best_t * direction;
        const glm::dvec2 folded = xz(fold(target, bits));
        if (glm::dot(edges_[0], folded) >= 0.0 && glm::dot(edges_[1], folded) >= 0.0) break;
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
