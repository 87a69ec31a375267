#pragma once
// Which stones of a piece share one view of their setting. On the GPU each group gets a
// virtual cube of the metal seen from its own centre (gpu/frame_renderer.cpp), in place of one
// cube seen from the piece's centre, from which the halo's small stones saw their own walls and
// beads with the parallax of a point millimetres away. A few large stones (a solitaire's, a
// trilogy's three) each have their own; smaller ones (a halo's, a band's) share one with their
// neighbours, so that a band of 36 stones needs four cubes, not 36.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "piece/piece.hpp"

namespace gem {

struct SightGroup {
    glm::dvec3 centre{0.0};           // where the group's cube is seen from: a member's girdle (mm)
    bool own = false;                 // one large stone alone
    std::vector<std::size_t> stones;  // indices into Piece::stones
};

inline constexpr std::size_t kMostSightGroups = 6;

// Every stone in exactly one group, at most kMostSightGroups groups.
std::vector<SightGroup> sight_groups(const Piece& piece);

}  // namespace gem
