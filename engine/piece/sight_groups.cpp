#include "piece/sight_groups.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "geometry/triangulate.hpp"

namespace gem {

namespace {

// A stone this share of the largest or more, among at most kOwnAtMost such, gets a cube alone.
constexpr double kOwnShare = 0.6;
constexpr std::size_t kOwnAtMost = 4;

// Where a stone's cube is seen from, in its own frame, whatever frame its file gave it: the
// middle of its girdle, at the level along its table's axis (its largest facet's normal) where
// the stone is widest. Its exits leave about the girdle, and the metal that holds it stands
// there: seen from the middle of its box, which lies in a brilliant's pavilion, the shipped
// pieces measured 0.1 to 0.3 ΔE00 further from the reference (docs/pieces.md).
glm::dvec3 girdle_middle(const Stone& stone) {
    const auto table = std::max_element(
        stone.facets.begin(), stone.facets.end(), [&](const Facet& a, const Facet& b) {
            return loop_area(stone.vertices, a.loop) < loop_area(stone.vertices, b.loop);
        });
    if (table == stone.facets.end() || table->loop.size() < 3) return glm::dvec3(0.0);
    const glm::dvec3 axis = table->plane.n;
    // The table's centroid: its fan of triangles, each at its centroid by its area.
    const std::vector<std::uint32_t>& loop = table->loop;
    glm::dvec3 middle(0.0);
    double area = 0.0;
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
        const glm::dvec3& a = stone.vertices[loop[0]];
        const glm::dvec3& b = stone.vertices[loop[k]];
        const glm::dvec3& c = stone.vertices[loop[k + 1]];
        const double w = 0.5 * glm::dot(glm::cross(b - a, c - a), axis);
        middle += w * (a + b + c) / 3.0;
        area += w;
    }
    if (area <= 0.0) return glm::dvec3(0.0);
    middle /= area;
    // Across the axis, the middle of the stone's extent along its outline's principal axes (a
    // heart's, a pear's line of symmetry and the one across it): the table of a heart lies
    // 0.3 mm off it, and seen from there the heart trilogy measured 0.2 ΔE00 further.
    const glm::dvec3 u = glm::normalize(glm::cross(
        axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 w = glm::cross(axis, u);
    double uu = 0.0, uw = 0.0, ww = 0.0;
    for (const glm::dvec3& v : stone.vertices) {
        const double a = glm::dot(v - middle, u);
        const double b = glm::dot(v - middle, w);
        uu += a * a;
        uw += a * b;
        ww += b * b;
    }
    const double angle = 0.5 * std::atan2(2.0 * uw, uu - ww);
    for (const glm::dvec3& e :
         {std::cos(angle) * u + std::sin(angle) * w, -std::sin(angle) * u + std::cos(angle) * w}) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const glm::dvec3& v : stone.vertices) {
            lo = std::min(lo, glm::dot(v - middle, e));
            hi = std::max(hi, glm::dot(v - middle, e));
        }
        middle += 0.5 * (lo + hi) * e;
    }
    const auto across = [&](const glm::dvec3& v) {
        const glm::dvec3 r = v - middle;
        return glm::length(r - glm::dot(r, axis) * axis);
    };
    double widest = 0.0;
    for (const glm::dvec3& v : stone.vertices) widest = std::max(widest, across(v));
    // The girdle has a thickness: the mean level of the corners within 2 % of the widest.
    double level = 0.0;
    int count = 0;
    for (const glm::dvec3& v : stone.vertices) {
        if (across(v) < 0.98 * widest) continue;
        level += glm::dot(v - middle, axis);
        ++count;
    }
    return middle + (level / count) * axis;
}

// Each stone, largest first, alone or joining the first shared group whose first stone lies
// within `join_factor` of that stone's radius.
std::vector<SightGroup> grouped(const std::vector<glm::dvec3>& centre,
                                const std::vector<glm::dvec3>& seen_from,
                                const std::vector<double>& radius,
                                const std::vector<std::size_t>& order, bool own_allowed,
                                double join_factor) {
    const double largest = radius[order.front()];
    std::vector<SightGroup> groups;
    for (const std::size_t i : order) {
        const bool own = own_allowed && radius[i] >= kOwnShare * largest;
        auto joins = [&](const SightGroup& g) {
            const std::size_t seed = g.stones.front();
            return !g.own && glm::length(centre[i] - centre[seed]) <= join_factor * radius[seed];
        };
        const auto group = own ? groups.end() : std::find_if(groups.begin(), groups.end(), joins);
        if (group != groups.end()) {
            group->stones.push_back(i);
        } else {
            groups.push_back({glm::dvec3(0.0), own, {i}});  // seen from: below
        }
    }
    for (SightGroup& g : groups) {
        glm::dvec3 sum(0.0);
        for (const std::size_t i : g.stones) sum += centre[i];
        // Seen from the member nearest the middle: a stone's centre lies inside the stone,
        // where the middle of an arc of stones may lie inside the metal between them.
        const glm::dvec3 middle = sum / static_cast<double>(g.stones.size());
        const auto nearest =
            std::min_element(g.stones.begin(), g.stones.end(), [&](std::size_t a, std::size_t b) {
                return glm::length(centre[a] - middle) < glm::length(centre[b] - middle);
            });
        g.centre = seen_from[*nearest];
    }
    return groups;
}

}  // namespace

std::vector<SightGroup> sight_groups(const Piece& piece) {
    if (piece.stones.empty()) return {};
    // Each stone's middle, the centre of its box in the piece's frame, and its radius about it:
    // what the stone is, whatever frame its file gave it (a glTF stone's origin may sit
    // off its girdle's centre).
    std::vector<glm::dvec3> girdle(piece.kinds.size());  // identical stones share their kind's
    for (std::size_t k = 0; k < piece.kinds.size(); ++k) girdle[k] = girdle_middle(piece.kinds[k]);
    std::vector<glm::dvec3> centre(piece.stones.size());
    std::vector<glm::dvec3> seen_from(piece.stones.size());
    std::vector<double> radius(piece.stones.size(), 0.0);
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        seen_from[i] = piece.stones[i].placement.to_piece(girdle[piece.stones[i].kind]);
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi = -lo;
        for (const glm::dvec3& v : piece.stone_of(i).vertices) {
            const glm::dvec3 p = piece.stones[i].placement.to_piece(v);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        centre[i] = 0.5 * (lo + hi);
        for (const glm::dvec3& v : piece.stone_of(i).vertices) {
            radius[i] =
                std::max(radius[i], glm::length(piece.stones[i].placement.to_piece(v) - centre[i]));
        }
    }
    std::vector<std::size_t> order(piece.stones.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return radius[a] > radius[b]; });
    const double largest = radius[order.front()];
    const auto large = static_cast<std::size_t>(std::count_if(
        radius.begin(), radius.end(), [&](double r) { return r >= kOwnShare * largest; }));
    const bool own_allowed = large <= kOwnAtMost;
    // Neighbours within three of a seed's radii share its cube; wider while there are too many.
    for (double join = 3.0;; join *= 1.5) {
        std::vector<SightGroup> groups =
            grouped(centre, seen_from, radius, order, own_allowed, join);
        if (groups.size() <= kMostSightGroups) return groups;
    }
}

}  // namespace gem
