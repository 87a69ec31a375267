// Attract mode: when it starts, what it does to the view and when it cycles presets and
// stones; the first touch takes over without a jump and is no tap.

#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "gesture_test_support.hpp"

namespace gem::kiosk {
namespace {

using test::frame;
using test::lift;

GestureOptions attract_options() {
    GestureOptions options;
    options.idle_s = 60.0;
    options.attract_deg_per_s = 12.0;
    options.attract_preset_s = 20.0;
    options.attract_stone_s = 60.0;
    options.attract_elevation_deg = 30.0;
    options.attract_ease_s = 4.0;
    return options;
}

const ViewState kStart{10.0, 45.0, 0.0, 1.0};

TEST(GestureAttract, StartsAfterIdleAndCyclesPresetsAndStones) {
    GestureController c = test::make_controller(kStart, attract_options());
    std::vector<std::pair<double, GestureAction>> seen;
    double started = -1.0;
    // Quarter-second frames: every time below is exact in binary.
    for (int i = 0; i <= 4 * 200; ++i) {
        const double t = 0.25 * i;
        c.advance(t);
        if (c.attract_mode() && started < 0.0) started = t;
        for (const GestureAction a : c.take_actions()) seen.emplace_back(t, a);
    }
    EXPECT_EQ(started, 60.0);  // idle_s after the clock started at 0
    const std::vector<std::pair<double, GestureAction>> expected = {
        {80.0, GestureAction::next_preset},  {100.0, GestureAction::next_preset},
        {120.0, GestureAction::next_stone},  {120.0, GestureAction::next_preset},
        {140.0, GestureAction::next_preset}, {160.0, GestureAction::next_preset},
        {180.0, GestureAction::next_stone},  {180.0, GestureAction::next_preset},
        {200.0, GestureAction::next_preset}};
    EXPECT_EQ(seen, expected);
}

TEST(GestureAttract, IdleCountsFromTheLastInput) {
    GestureController c = test::make_controller(kStart, attract_options());
    c.advance(0.0);
    c.on_event(frame(30.0, {Contact{1, {500.0, 500.0}}}));
    c.on_event(lift(31.0));
    c.advance(90.5);
    EXPECT_FALSE(c.attract_mode());
    c.advance(91.0);
    EXPECT_TRUE(c.attract_mode());
}

TEST(GestureAttract, NeverWhenIdleIsZero) {
    GestureOptions options = attract_options();
    options.idle_s = 0.0;
    GestureController c = test::make_controller(kStart, options);
    for (int i = 0; i <= 1000; ++i) c.advance(i);
    EXPECT_FALSE(c.attract_mode());
    EXPECT_TRUE(c.take_actions().empty());
    EXPECT_EQ(c.view().azimuth_deg, kStart.azimuth_deg);
}

TEST(GestureAttract, TurnsTheRingAndEasesTheView) {
    GestureController c = test::make_controller(kStart, attract_options());
    c.advance(0.0);
    // The shopper left the view at elevation 70, rolled 40 degrees and zoomed 2x.
    c.reset_view(ViewState{10.0, 70.0, 40.0, 2.0});
    c.advance(61.0);
    // Smoothstep s(u) = 3u^2 - 2u^3 over 4 s; at 1 s, u = 1/4: s = 3/16 - 2/64 = 0.15625.
    EXPECT_NEAR(c.view().elevation_deg, 70.0 - 40.0 * 0.15625, 1e-9);
    EXPECT_NEAR(c.view().azimuth_deg, 22.0, 1e-9);  // 12 deg/s for 1 s
    c.advance(62.0);                                // u = 1/2: s = 1/2
    EXPECT_NEAR(c.view().elevation_deg, 50.0, 1e-9);
    EXPECT_NEAR(c.view().roll_deg, 20.0, 1e-9);         // halfway back to the start view's 0
    EXPECT_NEAR(c.view().zoom, std::sqrt(2.0), 1e-12);  // geometrically halfway to 1
    c.advance(70.0);
    EXPECT_NEAR(c.view().elevation_deg, 30.0, 1e-9);
    EXPECT_NEAR(c.view().roll_deg, 0.0, 1e-9);
    EXPECT_NEAR(c.view().zoom, 1.0, 1e-12);
    EXPECT_NEAR(c.view().azimuth_deg, 10.0 + 120.0, 1e-9);
    c.advance(90.0);  // 30 s in: 10 + 360 = 370, which is 10
    EXPECT_NEAR(test::circular_difference(c.view().azimuth_deg, 10.0), 0.0, 1e-9);
    EXPECT_GE(c.view().azimuth_deg, -180.0);
    EXPECT_LT(c.view().azimuth_deg, 180.0);
}

TEST(GestureAttract, EasesWithoutAJump) {
    GestureController c = test::make_controller(kStart, attract_options());
    c.advance(0.0);
    c.reset_view(ViewState{10.0, 70.0, 0.0, 1.0});
    c.advance(59.0);
    double previous = c.view().elevation_deg;
    EXPECT_EQ(previous, 70.0);
    // The smoothstep's steepest slope is 1.5 / ease_s: 40 degrees over 4 s can change by at
    // most 15 deg/s, 0.25 degrees in a 1/60 s frame; and it starts from rest.
    double largest_step = 0.0;
    double first_step = -1.0;
    for (int i = 1; i <= 60 * 10; ++i) {
        c.advance(59.0 + i / 60.0);
        const double step = std::abs(c.view().elevation_deg - previous);
        if (c.attract_mode() && first_step < 0.0) first_step = step;
        largest_step = std::max(largest_step, step);
        previous = c.view().elevation_deg;
    }
    EXPECT_LE(largest_step, 15.0 / 60.0 + 1e-9);
    EXPECT_GT(largest_step, 0.9 * 15.0 / 60.0);  // it does ease, at about that pace
    EXPECT_LT(first_step, 0.01);
}

TEST(GestureAttract, TheElevationTargetStaysInsideTheBand) {
    GestureController c = test::make_controller(kStart, attract_options());
    c.set_elevation_limits(40.0, 80.0);
    c.advance(0.0);
    c.advance(100.0);
    EXPECT_NEAR(c.view().elevation_deg, 40.0, 1e-9);  // 30 is outside: its nearest edge
}

TEST(GestureAttract, FirstTouchTakesOverWithoutAJump) {
    GestureController c = test::make_controller(kStart, attract_options());
    c.advance(0.0);
    c.advance(75.0);
    ASSERT_TRUE(c.attract_mode());
    // The touch lands at 75.5 before any frame there: attract mode ran until then.
    c.on_event(frame(75.5, {Contact{1, {900.0, 500.0}}}));
    EXPECT_FALSE(c.attract_mode());
    const double azimuth = 10.0 + 12.0 * 15.5;  // 196: -164 in [-180, 180)
    EXPECT_NEAR(c.view().azimuth_deg, -164.0, 1e-9);
    EXPECT_NEAR(test::circular_difference(c.view().azimuth_deg, azimuth), 0.0, 1e-9);
    EXPECT_NEAR(c.view().elevation_deg, 30.0, 1e-9);
    // The drag goes on from there: 108 px right is 18 degrees less.
    test::move_finger(c, 1, {900.0, 500.0}, {1008.0, 500.0}, 75.5, 0.01, 12);
    EXPECT_NEAR(c.view().azimuth_deg, -182.0 + 360.0, 1e-9);
    const ViewState after_drag = c.view();
    c.advance(80.0);  // attract mode is over: nothing turns, no preset comes
    EXPECT_EQ(c.view().azimuth_deg, after_drag.azimuth_deg);
    EXPECT_TRUE(c.take_actions().empty());
}

TEST(GestureAttract, TheWakingTouchIsNoTap) {
    GestureController c = test::make_controller(kStart, attract_options());
    c.advance(0.0);
    c.advance(70.0);
    ASSERT_TRUE(c.attract_mode());
    c.on_event(frame(70.1, {Contact{1, {900.0, 500.0}}}));
    c.on_event(lift(70.2));
    EXPECT_FALSE(c.attract_mode());
    EXPECT_TRUE(c.take_actions().empty());
    // The next tap counts.
    c.on_event(frame(71.0, {Contact{1, {900.0, 500.0}}}));
    c.on_event(lift(71.1));
    EXPECT_EQ(c.take_actions(), std::vector<GestureAction>{GestureAction::next_stone});
}

TEST(GestureAttract, TheWheelEndsItAndZooms) {
    GestureController c = test::make_controller(kStart, attract_options());
    c.advance(0.0);
    c.advance(70.0);
    ASSERT_TRUE(c.attract_mode());
    const double zoom = c.view().zoom;
    c.on_event(WheelStep{70.0, 1.0, {0.0, 0.0}});
    EXPECT_FALSE(c.attract_mode());
    EXPECT_NEAR(c.view().zoom, zoom * 1.1, 1e-12);
    c.advance(129.5);
    EXPECT_FALSE(c.attract_mode());
    c.advance(130.0);
    EXPECT_TRUE(c.attract_mode());
}

TEST(GestureAttract, AStuckFingerDoesNotKeepItAway) {
    GestureController c = test::make_controller(kStart, attract_options());
    c.advance(0.0);
    c.on_event(frame(1.0, {Contact{1, {900.0, 500.0}}}));  // and never lifts
    c.advance(61.0);
    EXPECT_TRUE(c.attract_mode());
    c.advance(65.0);
    const ViewState at_move = c.view();
    // When that finger moves at last, it is a new touch: it takes over with no jump.
    c.on_event(frame(65.0, {Contact{1, {960.0, 500.0}}}));
    EXPECT_FALSE(c.attract_mode());
    EXPECT_EQ(c.view().azimuth_deg, at_move.azimuth_deg);
    c.on_event(frame(65.01, {Contact{1, {1020.0, 500.0}}}));
    EXPECT_NEAR(test::circular_difference(c.view().azimuth_deg, at_move.azimuth_deg), -10.0, 1e-9);
}

}  // namespace
}  // namespace gem::kiosk
