#include "piece/sight_groups.hpp"

#include <algorithm>
#include <numeric>

#include <limits>

namespace gem {

namespace {

// A stone this share of the largest or more, among at most kOwnAtMost such, gets a cube alone.
constexpr double kOwnShare = 0.6;
constexpr std::size_t kOwnAtMost = 4;

std::vector<SightGroup> grouped(const std::vector<glm::dvec3>& centre,
                                const std::vector<double>& radius,
                                const std::vector<std::size_t>& order, bool own_allowed,
                                double join_factor) {
    const double largest = radius[order.front()];
    std::vector<SightGroup> groups;
    std::vector<std::size_t> seed;  // each group's first stone
    for (const std::size_t i : order) {
        const glm::dvec3 c = centre[i];
        if (own_allowed && radius[i] >= kOwnShare * largest) {
            groups.push_back({c, radius[i], true, {i}});
            seed.push_back(i);
            continue;
        }
        bool joined = false;
        for (std::size_t g = 0; g < groups.size() && !joined; ++g) {
            if (groups[g].own) continue;
            if (glm::length(c - centre[seed[g]]) <= join_factor * radius[seed[g]]) {
                groups[g].stones.push_back(i);
                joined = true;
            }
        }
        if (!joined) {
            groups.push_back({c, radius[i], false, {i}});
            seed.push_back(i);
        }
    }
    for (SightGroup& g : groups) {
        glm::dvec3 sum(0.0);
        for (const std::size_t i : g.stones) sum += centre[i];
        // Seen from the member nearest the middle: a stone's centre lies inside the stone,
        // where the middle of an arc of stones may lie inside the metal between them.
        const glm::dvec3 middle = sum / static_cast<double>(g.stones.size());
        std::size_t nearest = g.stones.front();
        for (const std::size_t i : g.stones) {
            if (glm::length(centre[i] - middle) < glm::length(centre[nearest] - middle)) {
                nearest = i;
            }
        }
        g.centre = centre[nearest];
        g.reach_mm = 0.0;
        for (const std::size_t i : g.stones) {
            g.reach_mm = std::max(g.reach_mm, glm::length(centre[i] - g.centre) + radius[i]);
        }
    }
    return groups;
}

}  // namespace

std::vector<SightGroup> sight_groups(const Piece& piece) {
    if (piece.stones.empty()) return {};
    // Each stone's middle, the centre of its box in the piece's frame, and its radius about it:
    // what the stone is, whatever frame its file gave it (a glTF stone's origin may sit
    // off its girdle's centre).
    std::vector<glm::dvec3> centre(piece.stones.size());
    std::vector<double> radius(piece.stones.size(), 0.0);
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
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
        std::vector<SightGroup> groups = grouped(centre, radius, order, own_allowed, join);
        if (groups.size() <= kMostSightGroups) return groups;
    }
}

}  // namespace gem
