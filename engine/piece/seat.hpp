#pragma once
// Seating metal on a stone: the height at which a ball of metal, lowered straight down onto
// the stone at a given place, bears on its crown. A setter files a small seat into a claw or
// a bead where it meets the stone, so the ball is lowered until it overlaps the stone by
// kSeatMm, and never deeper: settings are checked against exactly that (no gap, no overlap
// beyond the seat).

#include <optional>

#include <glm/glm.hpp>

#include "geometry/stone.hpp"

namespace gem {

inline constexpr double kSeatMm = 0.02;
// Air left between the stone and metal that should not touch it (a gallery, a wall, a floor).
inline constexpr double kClearanceMm = 0.1;

// The centre of a ball of `radius`, lowered from `above` along `down` (unit, within a few
// degrees of −y: the stone's frame),
// where it overlaps the stone by kSeatMm; nothing when the ball is already in the stone at
// `above` or passes the girdle without meeting it.
std::optional<glm::dvec3> seat_ball(const Stone& stone, const glm::dvec3& above,
                                    const glm::dvec3& down, double radius);

}  // namespace gem
