// Taps and two-finger taps, and everything that is not one.

#include <vector>

#include <gtest/gtest.h>

#include "gesture_test_support.hpp"

namespace gem::kiosk {
namespace {

using test::frame;
using test::lift;
using Actions = std::vector<GestureAction>;

const ViewState kStart{0.0, 30.0, 0.0, 1.0};

TEST(GestureTap, ShortStillTouchIsATap) {
    GestureController c = test::make_controller(kStart);
    c.on_event(frame(1.00, {Contact{1, {500.0, 500.0}}}));
    c.on_event(frame(1.05, {Contact{1, {505.0, 503.0}}}));  // 5.8 px: under 12
    c.on_event(lift(1.15));
    EXPECT_EQ(c.take_actions(), Actions{GestureAction::next_stone});  // options.tap's default
    EXPECT_TRUE(c.take_actions().empty());                            // taken once
}

TEST(GestureTap, TheActionComesFromTheOptions) {
    GestureOptions options;
    options.tap = TapAction::next_preset;
    GestureController c = test::make_controller(kStart, options);
    c.on_event(frame(1.0, {Contact{1, {500.0, 500.0}}}));
    c.on_event(lift(1.1));
    EXPECT_EQ(c.take_actions(), Actions{GestureAction::next_preset});

    options.tap = TapAction::none;
    GestureController quiet = test::make_controller(kStart, options);
    quiet.on_event(frame(1.0, {Contact{1, {500.0, 500.0}}}));
    quiet.on_event(lift(1.1));
    EXPECT_TRUE(quiet.take_actions().empty());
}

TEST(GestureTap, ADragIsNotATap) {
    GestureController c = test::make_controller(kStart);
    test::move_finger(c, 1, {500.0, 500.0}, {530.0, 500.0}, 1.0, 0.02, 5);  // 30 px in 0.1 s
    c.on_event(lift(1.12));
    EXPECT_TRUE(c.take_actions().empty());
}

TEST(GestureTap, ADragThatComesBackIsNotATap) {
    GestureController c = test::make_controller(kStart);
    c.on_event(frame(1.00, {Contact{1, {500.0, 500.0}}}));
    c.on_event(frame(1.04, {Contact{1, {520.0, 500.0}}}));  // 20 px away
    c.on_event(frame(1.08, {Contact{1, {501.0, 500.0}}}));  // and back
    c.on_event(lift(1.10));
    EXPECT_TRUE(c.take_actions().empty());
}

TEST(GestureTap, ALongPressIsNotATap) {
    GestureController c = test::make_controller(kStart);
    c.on_event(frame(1.0, {Contact{1, {500.0, 500.0}}}));
    c.on_event(lift(1.3));  // tap_max_s is 0.25
    EXPECT_TRUE(c.take_actions().empty());
}

TEST(GestureTap, ATapDoesNotTurnOrSpinTheRing) {
    GestureController c = test::make_controller(kStart);
    // 10 px in 50 ms (33 deg/s) would be a fling if it were not a tap.
    c.on_event(frame(1.00, {Contact{1, {500.0, 500.0}}}));
    c.on_event(frame(1.05, {Contact{1, {510.0, 500.0}}}));
    c.on_event(lift(1.06));
    EXPECT_EQ(c.take_actions(), Actions{GestureAction::next_stone});
    const double at_lift = c.view().azimuth_deg;
    c.advance(2.0);
    EXPECT_EQ(c.view().azimuth_deg, at_lift);
}

TEST(GestureTap, TwoFingerTap) {
    GestureController c = test::make_controller(kStart);
    // The fingers land and lift in different frames, as real ones do.
    c.on_event(frame(1.00, {Contact{4, {500.0, 500.0}}}));
    c.on_event(frame(1.02, {Contact{4, {501.0, 500.0}}, Contact{5, {650.0, 480.0}}}));
    c.on_event(frame(1.12, {Contact{5, {652.0, 481.0}}}));
    c.on_event(lift(1.14));
    EXPECT_EQ(c.take_actions(), Actions{GestureAction::next_preset});  // the default
}

TEST(GestureTap, TwoFingersOneAfterTheOtherAreNoTap) {
    GestureController c = test::make_controller(kStart);
    c.on_event(frame(1.00, {Contact{1, {500.0, 500.0}}}));
    c.on_event(frame(1.05, {Contact{2, {500.0, 500.0}}}));  // 1 lifted, 2 landed
    c.on_event(lift(1.10));
    EXPECT_TRUE(c.take_actions().empty());
}

TEST(GestureTap, ThreeFingersAreNoTap) {
    GestureController c = test::make_controller(kStart);
    c.on_event(frame(1.00, {Contact{1, {500.0, 500.0}}, Contact{2, {600.0, 500.0}},
                            Contact{3, {700.0, 500.0}}}));
    c.on_event(lift(1.10));
    EXPECT_TRUE(c.take_actions().empty());
}

TEST(GestureTap, APinchIsNotATwoFingerTap) {
    GestureController c = test::make_controller(kStart);
    c.on_event(frame(1.00, {Contact{1, {500.0, 500.0}}, Contact{2, {600.0, 500.0}}}));
    c.on_event(frame(1.05, {Contact{1, {480.0, 500.0}}, Contact{2, {620.0, 500.0}}}));
    c.on_event(lift(1.10));
    EXPECT_TRUE(c.take_actions().empty());
}

}  // namespace
}  // namespace gem::kiosk
