#include "piece/piece.hpp"

#include <algorithm>
#include <cmath>

namespace gem {

double Piece::radius_mm() const {
    double r = metal.radius_mm();
    for (std::size_t i = 0; i < stones.size(); ++i) {
        for (const glm::dvec3& v : stone_of(i).vertices) {
            r = std::max(r, glm::length(stones[i].placement.to_piece(v)));
        }
    }
    return r;
}

std::string describe(const Piece& piece) {
    return "piece " + piece.name + ": " + std::to_string(piece.stones.size()) + " stones (" +
           std::to_string(piece.kinds.size()) + " distinct), " +
           std::to_string(piece.metal.triangle_count()) + " metal triangles";
}

}  // namespace gem
