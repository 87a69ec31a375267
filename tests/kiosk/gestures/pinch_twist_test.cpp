// Two-finger gestures and the wheel: pinch zoom, twist roll (checked with the engine's camera),
// fingers arriving and leaving without a jump.

#include <cmath>

#include <gtest/gtest.h>

#include "gesture_test_support.hpp"

namespace gem::kiosk {
namespace {

using test::frame;

const ViewState kStart{30.0, 40.0, 0.0, 1.0};
const glm::dvec2 kCentre{960.0, 540.0};

// Fingers 1 and 2 on opposite sides of kCentre, `radius` px from it, at `angle_deg` (measured
// in picture coordinates, y down: a growing angle turns clockwise on screen).
TouchFrame two_fingers(double time_s, double radius, double angle_deg) {
    const double a = angle_deg * test::kRadiansPerDegree;
    const glm::dvec2 offset = radius * glm::dvec2(std::cos(a), std::sin(a));
    return frame(time_s, {Contact{1, kCentre - offset}, Contact{2, kCentre + offset}});
}

// Pinch/twist from (radius0, angle0) to (radius1, angle1) in `steps` frames from t0.
double pinch(GestureController& c, double r0, double a0, double r1, double a1, double t0,
             int steps = 10) {
    for (int i = 0; i <= steps; ++i) {
        const double f = static_cast<double>(i) / steps;
        c.on_event(two_fingers(t0 + 0.01 * i, r0 + f * (r1 - r0), a0 + f * (a1 - a0)));
    }
    return t0 + 0.01 * steps;
}

TEST(GesturePinch, ZoomMultipliesByTheRatioOfFingerDistances) {
    GestureController c = test::make_controller(kStart);
    pinch(c, 100.0, 0.0, 150.0, 0.0, 1.0);  // 200 px apart -> 300 px apart
    EXPECT_NEAR(c.view().zoom, 1.5, 1e-12);
    EXPECT_NEAR(c.view().roll_deg, 0.0, 1e-12);
    EXPECT_NEAR(c.view().azimuth_deg, 30.0, 1e-12);  // two fingers do not turn the ring
    EXPECT_NEAR(c.view().elevation_deg, 40.0, 1e-12);
}

TEST(GesturePinch, OneFingerStillAndTheOtherMovingGivesTheSameRatio) {
    GestureController c = test::make_controller(ViewState{30.0, 40.0, 0.0, 2.0});
    for (int i = 0; i <= 10; ++i) {
        // 400 px apart -> 100 px apart: zoom x 0.25, from 2 to 0.5, held at min_zoom 0.6.
        c.on_event(frame(1.0 + 0.01 * i,
                         {Contact{1, {500.0, 500.0}}, Contact{2, {900.0 - 30.0 * i, 500.0}}}));
    }
    EXPECT_DOUBLE_EQ(c.view().zoom, 0.6);
}

TEST(GesturePinch, ZoomStaysInsideItsLimits) {
    GestureController c = test::make_controller(kStart);
    const double t = pinch(c, 50.0, 0.0, 500.0, 0.0, 1.0);  // x 10
    EXPECT_DOUBLE_EQ(c.view().zoom, 3.0);
    c.on_event(test::lift(t + 0.01));
    pinch(c, 300.0, 0.0, 200.0, 0.0, t + 0.5);  // x 2/3 from the limit: 2
    EXPECT_NEAR(c.view().zoom, 2.0, 1e-12);
}

// The picture grows with the fingers: two points of the stone, projected by gem::Camera, end up
// further apart on screen by the fingers' ratio.
TEST(GesturePinch, PictureScalesWithTheFingers) {
    GestureController c = test::make_controller(kStart);
    const glm::dvec3 a(0.3, -0.2, 0.1);
    const glm::dvec3 b(-0.4, 0.25, 0.3);
    const double before = glm::distance(test::project(kStart, a), test::project(kStart, b));
    pinch(c, 120.0, 10.0, 150.0, 10.0, 1.0);
    const double after = glm::distance(test::project(c.view(), a), test::project(c.view(), b));
    EXPECT_NEAR(after / before, 150.0 / 120.0, 1e-9);
}

TEST(GestureTwist, RollFollowsTheTurnOfTheFingers) {
    GestureController c = test::make_controller(kStart);
    pinch(c, 150.0, 0.0, 150.0, 30.0, 1.0);  // 30 degrees clockwise on screen
    EXPECT_NEAR(c.view().roll_deg, 30.0, 1e-9);
    EXPECT_NEAR(c.view().zoom, 1.0, 1e-12);
}

// The picture turns with the fingers: a point of the stone right of the picture's centre,
// projected by gem::Camera, turns about the centre by the fingers' angle in the same sense.
TEST(GestureTwist, PictureTurnsWithTheFingers) {
    const double turns[] = {30.0, -45.0, 100.0};
    const ViewState starts[] = {kStart, ViewState{-60.0, 75.0, 20.0, 1.3}};
    for (const ViewState& start : starts) {
        for (const double turn : turns) {
            GestureController c = test::make_controller(start);
            const glm::dvec3 p = 0.5 * test::camera_for(start).right();
            const glm::dvec2 centre(0.5 * test::kWidth, 0.5 * test::kHeight);
            const glm::dvec2 u = test::project(start, p) - centre;
            pinch(c, 150.0, 20.0, 150.0, 20.0 + turn, 1.0, 20);
            const glm::dvec2 v = test::project(c.view(), p) - centre;
            // Angles in picture coordinates (y down), as the fingers' were measured.
            const double turned =
                std::atan2(u.x * v.y - u.y * v.x, glm::dot(u, v)) / test::kRadiansPerDegree;
            EXPECT_NEAR(turned, turn, 1e-6) << "start roll " << start.roll_deg;
            EXPECT_NEAR(glm::length(v), glm::length(u), 1e-6);
        }
    }
}

TEST(GestureTwist, PinchAndTwistTogether) {
    GestureController c = test::make_controller(kStart);
    pinch(c, 100.0, 50.0, 120.0, 30.0, 1.0);
    EXPECT_NEAR(c.view().zoom, 1.2, 1e-12);
    EXPECT_NEAR(c.view().roll_deg, -20.0, 1e-9);
}

TEST(GesturePinch, MovingBothFingersTogetherChangesNothing) {
    GestureController c = test::make_controller(kStart);
    for (int i = 0; i <= 10; ++i) {
        const glm::dvec2 shift = static_cast<double>(i) * glm::dvec2(10.0, 5.0);
        c.on_event(frame(1.0 + 0.01 * i, {Contact{1, glm::dvec2(700.0, 500.0) + shift},
                                          Contact{2, glm::dvec2(900.0, 600.0) + shift}}));
    }
    EXPECT_NEAR(c.view().zoom, 1.0, 1e-12);
    EXPECT_NEAR(c.view().roll_deg, 0.0, 1e-9);
    EXPECT_NEAR(c.view().azimuth_deg, 30.0, 1e-12);
    EXPECT_NEAR(c.view().elevation_deg, 40.0, 1e-12);
}

TEST(GestureFingers, AddingAndLiftingFingersNeverJumps) {
    GestureController c = test::make_controller(kStart);
    // One finger drags 60 px right: -10 degrees.
    double t = test::move_finger(c, 1, {800.0, 540.0}, {860.0, 540.0}, 1.0, 0.01, 6);
    ViewState v = c.view();
    EXPECT_NEAR(v.azimuth_deg, 20.0, 1e-9);
    // A second finger lands far away, while the first moves on 6 px: nothing moves.
    t += 0.01;
    c.on_event(frame(t, {Contact{1, {866.0, 540.0}}, Contact{2, {1266.0, 240.0}}}));
    EXPECT_EQ(c.view().azimuth_deg, v.azimuth_deg);
    EXPECT_EQ(c.view().elevation_deg, v.elevation_deg);
    EXPECT_EQ(c.view().zoom, v.zoom);
    EXPECT_EQ(c.view().roll_deg, v.roll_deg);
    // Finger 2 moves away from finger 1 along their line: 500 px apart -> 750 px apart.
    t += 0.01;
    c.on_event(frame(t, {Contact{1, {866.0, 540.0}}, Contact{2, {1466.0, 90.0}}}));
    EXPECT_NEAR(c.view().zoom, 1.5, 1e-12);
    EXPECT_NEAR(c.view().roll_deg, 0.0, 1e-9);
    // A third finger lands: the zoom stays where it was.
    v = c.view();
    t += 0.01;
    c.on_event(frame(
        t, {Contact{1, {866.0, 540.0}}, Contact{2, {1466.0, 90.0}}, Contact{3, {400.0, 900.0}}}));
    EXPECT_EQ(c.view().zoom, v.zoom);
    EXPECT_EQ(c.view().roll_deg, v.roll_deg);
    // Finger 1 lifts: the other two carry on from where they are, nothing moves.
    t += 0.01;
    c.on_event(frame(t, {Contact{2, {1466.0, 90.0}}, Contact{3, {400.0, 900.0}}}));
    EXPECT_EQ(c.view().zoom, v.zoom);
    EXPECT_EQ(c.view().roll_deg, v.roll_deg);
    // Finger 3 lifts too: finger 2 alone turns the ring on from the current view.
    t += 0.01;
    c.on_event(frame(t, {Contact{2, {1466.0, 90.0}}}));
    v = c.view();
    test::move_finger(c, 2, {1466.0, 90.0}, {1406.0, 90.0}, t + 0.01, 0.01, 5);  // 60 px left
    EXPECT_NEAR(c.view().azimuth_deg, v.azimuth_deg + 10.0, 1e-9);
    EXPECT_EQ(c.view().zoom, v.zoom);
}

TEST(GestureWheel, EachNotchZoomsByTheStep) {
    GestureController c = test::make_controller(kStart);
    c.on_event(WheelStep{1.0, 2.0, {100.0, 100.0}});
    EXPECT_NEAR(c.view().zoom, 1.21, 1e-12);  // 1.1^2
    c.on_event(WheelStep{1.1, -1.0, {100.0, 100.0}});
    EXPECT_NEAR(c.view().zoom, 1.1, 1e-12);
    c.on_event(WheelStep{1.2, 40.0, {100.0, 100.0}});
    EXPECT_DOUBLE_EQ(c.view().zoom, 3.0);
    c.on_event(WheelStep{1.3, -80.0, {100.0, 100.0}});
    EXPECT_DOUBLE_EQ(c.view().zoom, 0.6);
    EXPECT_EQ(c.view().azimuth_deg, 30.0);
}

}  // namespace
}  // namespace gem::kiosk
