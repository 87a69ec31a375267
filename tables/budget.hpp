#pragma once
// `gemtables build --budget`: picks the cheapest build parameters (largest view spacing,
// smallest level, shallowest depth, highest weight threshold, dispersion off) for a stone
// shown a stated number of pixels across, under two stated budgets:
//
// - The picture: the mean CIEDE2000 over the stone's pixels (picture/image_error.hpp) of what
//   a table shows at a stored direction, against the exact picture. It is measured, not
//   modelled: for a few pilot views the exact CPU renderer draws what a table built with the
//   candidate parameters holds (traced at the candidate level, depth and threshold, spectral
//   only with dispersion), magnified to the screen size by nearest-texel lookup as
//   table.frag's texelFetch does, and compares it with the reference (depth 64, threshold
//   1e-6, 12 wavelengths, at the screen size). Dispersion stored as d(direction)/dn is a
//   first-order stand-in for the spectral trace the pilot uses; that difference is not
//   measured here.
// - The view: between stored directions the table shows a correct picture of the stone turned
//   by up to the spacing, and a faceted stone's picture is chaotic under turning (a diamond at
//   128 px differs by a mean ΔE00 of 14 from itself turned 0.8°), so no per-pixel budget can
//   be met between views at any spacing worth storing. The spacing is instead the largest
//   whose jump at the stone's rim, as the view passes from one stored view to the next, stays
//   within max_jump_px. The picture error at the median offset is measured and reported.
//
// The picture search relaxes one parameter at a time — dispersion first (it makes every
// later pilot render twelve times cheaper), then level (pixels go as level²), depth and
// threshold — each to the cheapest value that keeps the measured error within the budget with
// the others where they stand. It is greedy, so not the global optimum, but each step is
// measured with the relaxations before it in place: the final error is measured, not summed.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gemdb/database_types.hpp"
#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem::tables {

struct BudgetRequest {
    double budget_delta_e = 3.0;  // mean CIEDE2000 over the stone's pixels
    int screen_px = 256;          // pixels across the stone's bounding sphere on screen
    double max_jump_px = 8.0;     // rim movement when the shown view changes
    double min_elevation_deg = -10.0;
    // Pilot views (elevation°, azimuth°): the directions a shopper's turntable shows most.
    std::vector<std::pair<double, double>> pilot_views{{40.0, 7.0}, {70.0, 19.0}};
    // The values tried, cheapest first.
    std::vector<double> spacings_deg{12.0, 8.0, 6.0, 4.0, 3.0, 2.0};
    std::vector<std::uint32_t> levels{64, 128, 256, 512};
    std::vector<std::uint32_t> depths{4, 6, 8, 12, 16, 24, 32};
    std::vector<double> thresholds{1e-2, 1e-3, 1e-4, 1e-5};
};

struct BudgetStep {
    std::string parameter;  // "level", "depth", "threshold", "dispersion", "start"
    std::string value;
    double delta_e = 0.0;  // mean ΔE00 of the combined candidate, worst pilot view
    bool accepted = false;
};

struct BudgetChoice {
    BuildParams params;
    double spacing_deg = 0.0;
    double offset_deg = 0.0;       // median angle from a direction to its nearest stored view
    double delta_e = 0.0;          // error of the chosen parameters at a stored view, worst pilot
    double between_delta_e = 0.0;  // the same at the median offset from a stored view
    bool met = false;              // false: even the most accurate candidate exceeds the budget
    bool jump_met = false;         // false: even the finest spacing jumps more than max_jump_px
    std::vector<BudgetStep> steps;
};

// `on_step` reports each measurement as it is made (the command prints them). Errors: a
// budget or screen size that is not positive, or a render failure.
Result<BudgetChoice> choose_parameters(const Stone& stone, const BudgetRequest& request,
                                       const std::function<void(const BudgetStep&)>& on_step = {});

}  // namespace gem::tables
