#pragma once
// Where a stone sits in a piece: a rotation and a position taking the stone's own frame
// (docs/design.md, "Contracts") into the piece's frame, both in millimetres. Stones are scaled
// to size when they are made, so a placement is rigid and a stone's facets keep their angles.

#include <glm/glm.hpp>

namespace gem {

struct Placement {
    glm::dmat3 rotation{1.0};  // orthonormal, determinant +1
    glm::dvec3 position{0.0};  // of the stone's centre (its girdle centre)

    glm::dvec3 to_piece(const glm::dvec3& p) const { return rotation * p + position; }
    glm::dvec3 to_stone(const glm::dvec3& p) const {
        return glm::transpose(rotation) * (p - position);
    }
    glm::dvec3 direction_to_piece(const glm::dvec3& d) const { return rotation * d; }
    glm::dvec3 direction_to_stone(const glm::dvec3& d) const {
        return glm::transpose(rotation) * d;
    }
};

// The rotation whose columns are the stone frame's x, y and z axes in the piece: `up` is where
// the table faces, `along` (made perpendicular to it) where the stone's +x points.
glm::dmat3 frame_from_up(const glm::dvec3& up, const glm::dvec3& along);

}  // namespace gem
