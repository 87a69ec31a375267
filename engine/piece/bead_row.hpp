#pragma once
// A row of small stones set along a circle, as in a halo or an eternity band: each stone sits
// between two walls, clear of them and of the floor below, and is held by beads raised between
// it and its neighbours, each bead bearing on both crowns ("bead setting"; in a band the walls
// and the beads between the stones make the classic shared-bead row). The row's circle has its
// stones' tables facing along its axis (a halo: the stones look up beside the centre stone)
// or outward from it (a band: the stones look away from the finger).

#include <cstddef>

#include <glm/glm.hpp>

#include "piece/piece.hpp"
#include "util/result.hpp"

namespace gem {

struct RowCircle {
    glm::dvec3 centre{0.0};
    glm::dvec3 e0{1.0, 0.0, 0.0};  // the circle's plane: unit, perpendicular
    glm::dvec3 e1{0.0, 0.0, -1.0};
    double radius = 5.0;            // of the stones' girdle centres
    bool tables_along_axis = true;  // true: tables face e0 × e1; false: away from the centre
};

struct BeadRowParams {
    double gap_mm = 0.15;    // between neighbouring girdles, at the girdle circle
    double bead_pct = 20.0;  // bead radius as a share of the stone's width
    double wall_mm = 0.3;    // wall thickness
    int count = 0;           // stones in the full circle; 0: as many as fit
};

// Adds the stones of `kind` (in `piece.kinds`) around `circle`, their walls and beads, to the
// piece. Returns the number of stones set. Errors: a circle too small for three stones, a count
// that does not fit, a parameter out of range (named).
Result<int> add_bead_row(const BeadRowParams& params, const RowCircle& circle, std::size_t kind,
                         const std::string& role, Piece& piece);

// How many stones of `girdle_radius` fit round a circle of `circle_radius`, gap_mm apart.
int stones_that_fit(const BeadRowParams& params, double girdle_radius, double circle_radius);

}  // namespace gem
