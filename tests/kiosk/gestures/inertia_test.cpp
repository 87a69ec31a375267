// Flings: the speed at lift-off, its exponential decay, and when there is no spin at all.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "gesture_test_support.hpp"

namespace gem::kiosk {
namespace {

const ViewState kStart{0.0, 20.0, 0.0, 1.0};

// A drag to the right at 6 px per 10 ms frame (600 px/s) for 200 ms, the lift one report
// later: -600 px/s * (180 / 1080) deg/px = -100 deg/s of azimuth. Returns the lift time.
double fling_right(GestureController& c, double t0 = 1.0) {
    const double last = test::move_finger(c, 1, {600.0, 500.0}, {720.0, 500.0}, t0, 0.01, 20);
    c.on_event(test::lift(last + 0.01));
    return last + 0.01;
}

TEST(GestureInertia, SpinDecaysWithTheHalfLife) {
    GestureOptions options;
    options.inertia_half_life_s = 0.35;
    GestureController c = test::make_controller(kStart, options);
    const double lift = fling_right(c);
    const double at_lift = c.view().azimuth_deg;
    EXPECT_NEAR(at_lift, -20.0, 1e-9);  // 120 px of drag
    // v(t) = v0 2^(-t/h): the turn after time t is v0 tau (1 - 2^(-t/h)), tau = h / ln 2.
    const double v0 = -100.0;
    const double tau = 0.35 / std::numbers::ln2;
    c.advance(lift + 0.35);
    EXPECT_NEAR(test::circular_difference(c.view().azimuth_deg, at_lift), v0 * tau * 0.5, 1e-6);
    c.advance(lift + 0.70);
    EXPECT_NEAR(test::circular_difference(c.view().azimuth_deg, at_lift), v0 * tau * 0.75, 1e-6);
    c.advance(lift + 30.0);
    EXPECT_NEAR(test::circular_difference(c.view().azimuth_deg, at_lift), v0 * tau,
                2e-3);  // settled
    EXPECT_NEAR(c.view().elevation_deg, 20.0, 1e-9);
}

TEST(GestureInertia, SpinDoesNotDependOnTheFrameRate) {
    GestureController once = test::make_controller(kStart);
    GestureController often = test::make_controller(kStart);
    const double lift = fling_right(once);
    fling_right(often);
    once.advance(lift + 0.5);
    for (int i = 1; i <= 30; ++i) often.advance(lift + i * (0.5 / 30));
    EXPECT_NEAR(once.view().azimuth_deg, often.view().azimuth_deg, 1e-9);
}

// The speed comes from the whole recent drag, not the last step: one frame 3 px off changes
// a least-squares slope over nine 10 ms samples by 3 * 0.04 / 0.006 = 20 px/s (3 %), where the
// last step alone would say 900 px/s instead of 600 (50 %).
TEST(GestureInertia, OneNoisySampleBarelyChangesTheFling) {
    GestureOptions options;
    options.inertia_half_life_s = 0.35;
    GestureController c = test::make_controller(kStart, options);
    const double last = test::move_finger(c, 1, {600.0, 500.0}, {714.0, 500.0}, 1.0, 0.01, 19);
    c.on_event(test::frame(last + 0.01, {Contact{1, {723.0, 500.0}}}));  // 720 + 3 px noise
    c.on_event(test::lift(last + 0.02));
    const double at_lift = c.view().azimuth_deg;
    c.advance(last + 0.02 + 30.0);
    const double tau = 0.35 / std::numbers::ln2;
    const double speed = -(test::circular_difference(c.view().azimuth_deg, at_lift)) /
                         tau;  // the whole glide is v0 tau
    EXPECT_NEAR(speed, 100.0, 6.0);
}

TEST(GestureInertia, NoSpinAfterTheFingerStopped) {
    GestureController c = test::make_controller(kStart);
    const double last = test::move_finger(c, 1, {600.0, 500.0}, {720.0, 500.0}, 1.0, 0.01, 20);
    // The finger rests 150 ms (a panel reports nothing meanwhile), then lifts.
    c.on_event(test::lift(last + 0.15));
    const ViewState at_lift = c.view();
    c.advance(last + 2.0);
    EXPECT_EQ(c.view().azimuth_deg, at_lift.azimuth_deg);
}

TEST(GestureInertia, NoSpinAfterASlowDrag) {
    GestureController c = test::make_controller(kStart);
    // 30 px/s is 5 deg/s, under fling_min_deg_per_s (15).
    const double last = test::move_finger(c, 1, {600.0, 500.0}, {615.0, 500.0}, 1.0, 0.01, 50);
    c.on_event(test::lift(last + 0.01));
    const double at_lift = c.view().azimuth_deg;
    c.advance(last + 2.0);
    EXPECT_EQ(c.view().azimuth_deg, at_lift);
}

TEST(GestureInertia, NoSpinWhenThePanelReportedTheRestingFinger) {
    GestureController c = test::make_controller(kStart);
    double t = test::move_finger(c, 1, {600.0, 500.0}, {720.0, 500.0}, 1.0, 0.01, 20);
    // Some panels keep reporting a resting finger: 100 ms of frames at the same place.
    t = test::move_finger(c, 1, {720.0, 500.0}, {720.0, 500.0}, t + 0.01, 0.01, 10);
    c.on_event(test::lift(t + 0.01));
    const double at_lift = c.view().azimuth_deg;
    c.advance(t + 2.0);
    EXPECT_EQ(c.view().azimuth_deg, at_lift);
}

TEST(GestureInertia, ATouchStopsTheSpinAtOnce) {
    GestureController c = test::make_controller(kStart);
    const double lift = fling_right(c);
    c.advance(lift + 0.1);
    const double spinning = c.view().azimuth_deg;
    c.on_event(test::frame(lift + 0.2, {Contact{2, {300.0, 300.0}}}));
    // The spin ran on until the touch (0.2 s after the lift), and not a moment longer.
    const double tau = 0.35 / std::numbers::ln2;
    const double at_touch = -20.0 - 100.0 * tau * (1.0 - std::exp(-0.2 / tau));
    EXPECT_NEAR(c.view().azimuth_deg, at_touch, 1e-6);
    EXPECT_LT(c.view().azimuth_deg, spinning);
    c.advance(lift + 1.0);
    EXPECT_NEAR(c.view().azimuth_deg, at_touch, 1e-6);
    // Lifting the still finger: no new spin.
    c.on_event(test::lift(lift + 1.1));
    c.advance(lift + 3.0);
    EXPECT_NEAR(c.view().azimuth_deg, at_touch, 1e-6);
}

TEST(GestureInertia, FlingSpeedIsCapped) {
    GestureOptions options;
    options.fling_max_deg_per_s = 200.0;
    GestureController c = test::make_controller(kStart, options);
    // 60 px per 10 ms: 1000 deg/s, capped to 200.
    const double last = test::move_finger(c, 1, {100.0, 500.0}, {700.0, 500.0}, 1.0, 0.01, 10);
    c.on_event(test::lift(last + 0.01));
    const double at_lift = c.view().azimuth_deg;
    c.advance(last + 30.0);
    EXPECT_NEAR(test::circular_difference(c.view().azimuth_deg, at_lift),
                -200.0 * 0.35 / std::numbers::ln2, 2e-3);
}

TEST(GestureInertia, SpinIntoTheElevationLimitGoesOnAboutTheVerticalAxis) {
    GestureController c = test::make_controller(kStart);
    c.set_elevation_limits(0.0, 25.0);
    // Diagonal: 6 px right and 3 px down per 10 ms: -100 deg/s azimuth, +50 deg/s elevation;
    // the 60 px down turn 20 -> 30 is held at 25 already.
    const double last = test::move_finger(c, 1, {600.0, 500.0}, {720.0, 560.0}, 1.0, 0.01, 20);
    c.on_event(test::lift(last + 0.01));
    EXPECT_DOUBLE_EQ(c.view().elevation_deg, 25.0);
    const double at_lift = c.view().azimuth_deg;
    c.advance(last + 0.01 + 0.35);
    EXPECT_DOUBLE_EQ(c.view().elevation_deg, 25.0);
    EXPECT_NEAR(test::circular_difference(c.view().azimuth_deg, at_lift),
                -100.0 * 0.35 / std::numbers::ln2 * 0.5, 1e-6);
}

TEST(GestureInertia, NoSpinAfterAPinch) {
    GestureController c = test::make_controller(kStart);
    for (int i = 0; i <= 10; ++i) {
        const double x = 10.0 * i;
        c.on_event(test::frame(1.0 + 0.01 * i,
                               {Contact{1, {800.0 - x, 500.0}}, Contact{2, {1000.0 + x, 500.0}}}));
    }
    c.on_event(test::lift(1.11));
    const ViewState at_lift = c.view();
    c.advance(3.0);
    EXPECT_EQ(c.view().azimuth_deg, at_lift.azimuth_deg);
    EXPECT_EQ(c.view().elevation_deg, at_lift.elevation_deg);
}

}  // namespace
}  // namespace gem::kiosk
