#pragma once
// Claws that hold one stone, as a jeweller makes them: each rises from below beside the
// pavilion, bears on the girdle and is bent over the crown, where its rounded end rests just
// inside the girdle. The end stands as high as GIA's quality-assurance benchmark for a prong
// setting asks: 90 to 100 % of the height from the girdle to the top of the table (GIA,
// "Setting a princess-cut center stone in a platinum mounting with V-prongs", gia.edu).

#include <cstddef>
#include <vector>

#include "geometry/stone.hpp"
#include "piece/metal_mesh.hpp"
#include "piece/piece.hpp"
#include "util/result.hpp"

namespace gem {

struct ClawParams {
    int claws = 4;
    double width_mm = 0.0;  // the wire's diameter (the tip's ball is a little larger); 0: fit
                            // the stone (an eighth of its width, thinner on a low crown)
    double tip_height_pct = 95.0;  // the tip's top, as a share of girdle-to-table height
    double first_deg = 45.0;       // azimuth of the first claw about the stone's axis
};

// The claws' width before any thinning for a low crown: the one asked for, or an eighth of the
// stone's width (0.3 to 1.2 mm).
double claw_width(const ClawParams& params, const Stone& stone);

// Adds the claws of the stone `stones[index]` (placed in the piece) to `metal`, their feet
// reaching down to `foot_y` in the stone's frame (into whatever carries them), with a gallery
// rail joining them under the culet; each tip is recorded as a Hold. Errors name the
// parameter: a claw count or width out of range, a tip height that no place on the crown
// gives.
Result<bool> add_claws(const ClawParams& params, const Stone& stone, std::size_t index,
                       const Placement& placement, double foot_y, MetalMesh& metal,
                       std::vector<Hold>& holds);

}  // namespace gem
