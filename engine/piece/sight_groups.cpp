#include "piece/sight_groups.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace gem {

namespace {

// A stone this share of the largest or more, among at most kOwnAtMost such, gets a cube alone.
constexpr double kOwnShare = 0.6;
constexpr std::size_t kOwnAtMost = 4;

// Each stone, largest first, alone or joining the first shared group whose first stone lies
// within `join_factor` of that stone's radius.
std::vector<SightGroup> grouped(const std::vector<glm::dvec3>& centre,
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
            groups.push_back({centre[i], own, {i}});
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
        g.centre = centre[*nearest];
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
