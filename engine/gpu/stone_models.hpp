#pragma once
// Each stone of a piece modelled no more than the picture needs. A 1.3 mm stone covering a few
// hundred pixels does not need the centre stone's depth or exact fire: its model (StoneModel:
// depth, fire) is chosen from its size on screen by measurement. For each kind of stone other
// than the centre stone's (which keeps the configured model, the hero of the picture), the
// kind is drawn alone at the size it has on screen, seen from where the view sees it, with
// the configured model and with each cheaper one; the cheapest whose mean ΔE00 against the
// configured one is within the budget is kept. A piece of one kind only (a band) has no hero,
// and its one kind is chosen for too. The measurement is of the GPU against itself; how the
// configured model stands against the exact reference, by stone size and depth, is the
// small-stone chart (bench_small_stones, docs/pieces.md).

#include <cstddef>
#include <string>
#include <vector>

#include "gpu/frame_renderer.hpp"
#include "picture/camera.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// The kiosk's error budget: a mean ΔE00 of 3 over a stone, the budget the default catalogue's
// tables are chosen under (config/CMakeLists.txt, tables/budget.hpp).
inline constexpr double kStoneModelBudgetDeltaE = 3.0;

// The models a kind may be given, cheapest first, the configured one last: every depth of
// 1, 2, 3, 4 and 6 below the configured depth, then the configured depth, each with no fire,
// first-order fire and exact fire in that order up to the configured fire.
std::vector<StoneModel> cheaper_models(const StoneModel& configured);

// The first candidate whose error is within the budget; the last (the configured model)
// when none is. `errors` holds one mean ΔE00 per candidate.
std::size_t first_within(const std::vector<double>& errors, double budget);

struct ModelChoice {
    std::size_t kind = 0;
    double width_px = 0.0;  // the stone's bounding diameter on screen
    StoneModel model;       // chosen
    StoneModel configured;
    double delta_e = 0.0;  // mean ΔE00 of the chosen model against the configured one
    int candidates = 0;    // models measured
};

// Chooses and sets the model of every kind but the centre stone's (see above) for `view`,
// drawing off screen (the caller's framebuffer and viewport are kept). For a method without
// models (StoneMethod::model: all but the trace) nothing is chosen and the list is empty; nor
// for a kind drawn from its tables (piece_tables.hpp).
Result<std::vector<ModelChoice>> choose_stone_models(FrameRenderer& renderer, const Camera& view,
                                                     double budget = kStoneModelBudgetDeltaE);

// One log phrase: "1.3 mm round brilliant (x22), 58 px: depth 3, first-order fire (ΔE00 2.1
// against depth 8; 6 models measured)".
std::string describe(const ModelChoice& choice, const FrameRenderer& renderer,
                     std::size_t instances);

}  // namespace gem::gpu
