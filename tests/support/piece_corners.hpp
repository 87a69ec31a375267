#pragma once
// How far apart two readings of one piece put a stone: the farthest any corner of stone `i` of
// `a` lies from the nearest corner of stone `i` of `b`, both in the piece's frame (mm). Corners,
// not facets, so that a reader that re-triangulates or re-centres a stone still compares.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "piece/piece.hpp"

namespace gem::test_support {

inline double corner_gap(const Piece& a, const Piece& b, std::size_t i) {
    double worst = 0.0;
    for (const glm::dvec3& v : a.stone_of(i).vertices) {
        const glm::dvec3 p = a.stones[i].placement.to_piece(v);
        double nearest = HUGE_VAL;
        for (const glm::dvec3& w : b.stone_of(i).vertices) {
            nearest = std::min(nearest, glm::length(p - b.stones[i].placement.to_piece(w)));
        }
        worst = std::max(worst, nearest);
    }
    return worst;
}

// The farthest any corner of the piece's stone `stone` lies from the nearest of `expected`,
// corners in the piece's frame (mm): a stone against what it was made from.
inline double corner_error(const Piece& piece, std::size_t stone,
                           const std::vector<glm::dvec3>& expected) {
    double worst = 0.0;
    const PieceStone& s = piece.stones[stone];
    for (const glm::dvec3& v : piece.kinds[s.kind].vertices) {
        const glm::dvec3 p = s.placement.to_piece(v);
        double best = HUGE_VAL;
        for (const glm::dvec3& e : expected) best = std::min(best, glm::length(p - e));
        worst = std::max(worst, best);
    }
    return worst;
}

}  // namespace gem::test_support
