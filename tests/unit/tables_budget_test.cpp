// gemtables' parameter choice under an error budget (tables/budget.hpp): the spacing rule
// against a hand calculation, the extremes of the budget, and the chosen parameters' error
// measured again here, through the reference renderer, independently of the search.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "budget.hpp"
#include "cpu/reference_render.hpp"
#include "geometry/cuts.hpp"
#include "optics/material.hpp"
#include "picture/image_error.hpp"
#include "scene/scene.hpp"

namespace gem::tables {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

const Stone& diamond() {
    static const Stone stone =
        make_cut(default_cut_params(CutShape::round_brilliant), *find_material("diamond")).value();
    return stone;
}

// Small pictures and short candidate lists: the search's logic, not its figures.
BudgetRequest small_request(double budget) {
    BudgetRequest r;
    r.budget_delta_e = budget;
    r.screen_px = 48;
    r.pilot_views = {{50.0, 7.0}};
    r.spacings_deg = {2.0, 3.0, 4.0, 6.0};
    r.levels = {16, 32, 48};
    r.depths = {2, 8, 24};
    r.thresholds = {1e-1, 1e-4};
    return r;
}

TEST(TablesBudget, SpacingIsTheLargestWithinTheJump) {
    BudgetRequest r = small_request(100.0);
    // 48 px across: the rim is 24 px from the centre, so a turn of θ moves it 24 θ pixels.
    // A 1.5 px budget allows θ ≤ 1.5 / 24 rad = 3.58°: 3° of {2, 3, 4, 6}.
    r.max_jump_px = 1.5;
    const auto c = choose_parameters(diamond(), r);
    ASSERT_TRUE(c.ok()) << c.error();
    EXPECT_DOUBLE_EQ(c.value().spacing_deg, 3.0);
    EXPECT_NEAR(c.value().params.grid.spacing_rad, 3.0 * kDegree, 1e-12);
    EXPECT_TRUE(c.value().jump_met);
    // The median offset to the nearest view is below the spacing (a view's cell is about a
    // spacing across) and not zero.
    EXPECT_GT(c.value().offset_deg, 0.1);
    EXPECT_LT(c.value().offset_deg, 3.0);

    r.max_jump_px = 0.1;  // 0.24° would be needed: even 2° is over, and that is said
    const auto fine = choose_parameters(diamond(), r);
    ASSERT_TRUE(fine.ok()) << fine.error();
    EXPECT_DOUBLE_EQ(fine.value().spacing_deg, 2.0);
    EXPECT_FALSE(fine.value().jump_met);
}

TEST(TablesBudget, AGenerousBudgetTakesTheCheapestOfEverything) {
    // A mean ΔE00 of 100 is black against white: any picture of the stone is within it.
    const auto c = choose_parameters(diamond(), small_request(100.0));
    ASSERT_TRUE(c.ok()) << c.error();
    const BuildParams& p = c.value().params;
    EXPECT_TRUE(c.value().met);
    EXPECT_FALSE(p.dispersion);
    EXPECT_EQ(p.levels.back(), 16u);
    EXPECT_EQ(p.max_depth, 2u);
    EXPECT_DOUBLE_EQ(p.weight_threshold, 1e-1);
}

TEST(TablesBudget, AnImpossibleBudgetKeepsTheMostAccurateAndSaysSo) {
    const auto c = choose_parameters(diamond(), small_request(1e-3));
    ASSERT_TRUE(c.ok()) << c.error();
    const BuildParams& p = c.value().params;
    EXPECT_FALSE(c.value().met);
    EXPECT_TRUE(p.dispersion);
    EXPECT_EQ(p.levels.back(), 48u);  // the smallest level covering 48 px
    EXPECT_EQ(p.max_depth, 24u);
    EXPECT_DOUBLE_EQ(p.weight_threshold, 1e-4);
    ASSERT_EQ(c.value().steps.size(), 1u);  // nothing relaxed
}

// The chosen parameters' picture drawn here through the reference renderer with the same
// definitions (traced at the chosen level, magnified by nearest texel, against depth 64 and
// 12 wavelengths): its error must be within the budget, and cheaper choices must have been
// tried and refused.
TEST(TablesBudget, ChosenParametersMeetTheBudgetWhenMeasuredAgain) {
    const BudgetRequest r = small_request(4.0);
    const auto c = choose_parameters(diamond(), r);
    ASSERT_TRUE(c.ok()) << c.error();
    ASSERT_TRUE(c.value().met);
    const BuildParams& p = c.value().params;

    auto draw = [&](int side, int depth, double threshold, bool spectral) {
        RenderSettings s;
        s.width = s.height = side;
        s.samples_per_pixel = 1;
        s.camera.elevation_deg = r.pilot_views[0].first;
        s.camera.azimuth_deg = r.pilot_views[0].second;
        s.shading.lights = default_scene().lights;
        s.trace.max_depth = depth;
        s.trace.min_weight = threshold;
        s.spectral = spectral;
        s.background_is_environment = false;
        return render_reference(diamond(), Environment::studio(), s).value();
    };
    const Image reference = draw(r.screen_px, 64, 1e-6, true);
    const int level = static_cast<int>(p.levels.back());
    const Image stored =
        draw(level, static_cast<int>(p.max_depth), p.weight_threshold, p.dispersion);
    Image shown(r.screen_px, r.screen_px);
    for (int y = 0; y < r.screen_px; ++y)
        for (int x = 0; x < r.screen_px; ++x)
            shown.at(x, y) = stored.at(x * level / r.screen_px, y * level / r.screen_px);
    ErrorOptions options;
    options.only_stone = true;
    const auto e = compare_images(shown, reference, options);
    ASSERT_TRUE(e.ok()) << e.error();
    EXPECT_LE(e.value().delta_e_mean, r.budget_delta_e);
    EXPECT_NEAR(e.value().delta_e_mean, c.value().delta_e, 1e-9);

    // Every step the search accepted was within budget; every refused one was over it.
    for (const BudgetStep& s : c.value().steps)
        EXPECT_EQ(s.accepted, s.delta_e <= r.budget_delta_e) << s.parameter << " " << s.value;
    const bool refused_something = std::any_of(c.value().steps.begin(), c.value().steps.end(),
                                               [](const BudgetStep& s) { return !s.accepted; });
    EXPECT_TRUE(refused_something) << "a budget of 4 should not allow every cheapest value";
}

TEST(TablesBudget, RefusesBadRequests) {
    BudgetRequest r = small_request(0.0);
    EXPECT_FALSE(choose_parameters(diamond(), r).ok());
    r = small_request(2.0);
    r.screen_px = 4;
    EXPECT_FALSE(choose_parameters(diamond(), r).ok());
    r = small_request(2.0);
    r.levels.clear();
    EXPECT_FALSE(choose_parameters(diamond(), r).ok());
}

}  // namespace
}  // namespace gem::tables
