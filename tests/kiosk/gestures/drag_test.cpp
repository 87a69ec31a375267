// One-finger drags: gain, direction (checked with the engine's camera), clamping.

#include <gtest/gtest.h>

#include "gesture_test_support.hpp"

namespace gem::kiosk {
namespace {

using test::kDegreesPerPx;

ViewState view_at(double azimuth, double elevation, double roll = 0.0, double zoom = 1.0) {
    return ViewState{azimuth, elevation, roll, zoom};
}

TEST(GestureDrag, HorizontalDragTurnsAzimuthByTheGain) {
    GestureController c = test::make_controller(view_at(40.0, 30.0));
    // 108 px is a tenth of the picture's 1080 px height: 18 degrees at 180 per height. Right
    // lowers the azimuth (turntable.hpp: the front point's screen x is r cos el sin(az0 - az)).
    test::move_finger(c, 1, {900.0, 500.0}, {1008.0, 500.0}, 1.0, 0.01, 12);
    EXPECT_NEAR(c.view().azimuth_deg, 22.0, 1e-9);
    EXPECT_NEAR(c.view().elevation_deg, 30.0, 1e-9);
    EXPECT_EQ(c.view().roll_deg, 0.0);
    EXPECT_EQ(c.view().zoom, 1.0);
}

TEST(GestureDrag, VerticalDragTurnsElevationByTheGain) {
    GestureController c = test::make_controller(view_at(40.0, 30.0));
    // 54 px down: 9 degrees, and down raises the elevation.
    test::move_finger(c, 1, {900.0, 500.0}, {900.0, 554.0}, 1.0, 0.01, 6);
    EXPECT_NEAR(c.view().elevation_deg, 39.0, 1e-9);
    EXPECT_NEAR(c.view().azimuth_deg, 40.0, 1e-9);
}

TEST(GestureDrag, GainFollowsOptionAndPictureHeight) {
    GestureOptions options;
    options.degrees_per_picture_height = 90.0;
    GestureController c(options, view_at(0.0, 0.0));
    c.set_picture_size({800.0, 600.0});
    // 60 px of a 600 px height at 90 degrees per height: 9 degrees.
    test::move_finger(c, 1, {100.0, 100.0}, {160.0, 100.0}, 1.0, 0.01, 3);
    EXPECT_NEAR(c.view().azimuth_deg, -9.0, 1e-9);
}

// The stone must follow the finger: its front surface, projected by gem::Camera before and
// after a small drag, moves in the drag's direction on screen. Along the picture's axes (with
// the picture rolled by a quarter turn, the axes swap roles) the direction is exact to first
// order: |cos| > 0.9995 allows 1.8 degrees for the second-order terms of a 2-degree turn.
TEST(GestureDrag, FrontSurfaceFollowsTheFingerOnScreen) {
    const ViewState views[] = {view_at(0.0, 0.0),          view_at(40.0, 30.0),
                               view_at(-120.0, -20.0),     view_at(75.0, 60.0, 90.0),
                               view_at(10.0, 25.0, 180.0), view_at(170.0, 45.0, -90.0, 2.0)};
    const glm::dvec2 drags[] = {{12.0, 0.0}, {-12.0, 0.0}, {0.0, 12.0}, {0.0, -12.0}};
    for (const ViewState& start : views) {
        for (const glm::dvec2& drag : drags) {
            GestureController c = test::make_controller(start);
            const glm::dvec3 p = test::front_point(start);
            const glm::dvec2 before = test::project(start, p);
            test::move_finger(c, 1, {960.0, 540.0}, glm::dvec2(960.0, 540.0) + drag, 1.0, 0.01, 4);
            const glm::dvec2 moved = test::project(c.view(), p) - before;
            EXPECT_GT(glm::length(moved), 1.0);
            EXPECT_GT(glm::dot(glm::normalize(moved), glm::normalize(drag)), 0.9995)
                << "view az " << start.azimuth_deg << " el " << start.elevation_deg << " roll "
                << start.roll_deg << ", drag (" << drag.x << ", " << drag.y << "), moved ("
                << moved.x << ", " << moved.y << ")";
        }
    }
}

// Diagonal drags, or drags in a picture rolled by an odd angle, mix azimuth and elevation. A
// turn about the vertical axis moves the front point by cos(elevation) less than the same turn
// in elevation (the point sits that far from the axis), so the on-screen direction bends
// toward the elevation's share by at most atan(1 / sqrt(c)) - atan(sqrt(c)), c = cos(el) (the
// largest angle between (a c, b) and (a, b)); it never leaves the drag's side.
TEST(GestureDrag, FrontSurfaceFollowsDiagonalDrags) {
    const ViewState views[] = {view_at(40.0, 30.0, 0.0), view_at(75.0, 60.0, 90.0),
                               view_at(10.0, -25.0, -135.0), view_at(170.0, 45.0, 30.0, 2.0)};
    const glm::dvec2 drags[] = {{9.0, -7.0}, {-5.0, -11.0}, {12.0, 0.0}, {0.0, 12.0}};
    for (const ViewState& start : views) {
        const double c = std::cos(start.elevation_deg * test::kRadiansPerDegree);
        const double bend_deg =
            (std::atan(1.0 / std::sqrt(c)) - std::atan(std::sqrt(c))) / test::kRadiansPerDegree;
        const double min_cos = std::cos((bend_deg + 2.0) * test::kRadiansPerDegree);
        for (const glm::dvec2& drag : drags) {
            GestureController controller = test::make_controller(start);
            const glm::dvec3 p = test::front_point(start);
            const glm::dvec2 before = test::project(start, p);
            test::move_finger(controller, 1, {960.0, 540.0}, glm::dvec2(960.0, 540.0) + drag, 1.0,
                              0.01, 4);
            const glm::dvec2 moved = test::project(controller.view(), p) - before;
            EXPECT_GT(glm::dot(glm::normalize(moved), glm::normalize(drag)), min_cos)
                << "view az " << start.azimuth_deg << " el " << start.elevation_deg << " roll "
                << start.roll_deg << ", drag (" << drag.x << ", " << drag.y << "), moved ("
                << moved.x << ", " << moved.y << ")";
        }
    }
}

// Pushing the front surface down tilts the table (+y, the stone frame's up) toward the viewer.
TEST(GestureDrag, DownwardDragTiltsTheTableTowardTheViewer) {
    const ViewState start = view_at(30.0, 20.0);
    GestureController c = test::make_controller(start);
    test::move_finger(c, 1, {960.0, 400.0}, {960.0, 460.0}, 1.0, 0.01, 6);
    const glm::dvec3 table_normal(0.0, 1.0, 0.0);
    const double facing_before = -glm::dot(table_normal, test::camera_for(start).forward());
    const double facing_after = -glm::dot(table_normal, test::camera_for(c.view()).forward());
    // sin(20 deg) before; 60 px = 10 deg more elevation: sin(30 deg) = 0.5 after.
    EXPECT_NEAR(facing_before, std::sin(20.0 * test::kRadiansPerDegree), 1e-12);
    EXPECT_NEAR(facing_after, 0.5, 1e-12);
}

TEST(GestureDrag, ElevationStaysInsideTheDatabaseBand) {
    GestureController c = test::make_controller(view_at(0.0, 30.0));
    c.set_elevation_limits(10.0, 60.0);
    // Down by half the picture (90 degrees) would reach 120: held at 60.
    double t = test::move_finger(c, 1, {960.0, 200.0}, {960.0, 740.0}, 1.0, 0.01, 20);
    EXPECT_DOUBLE_EQ(c.view().elevation_deg, 60.0);
    // Back up 54 px: 9 degrees down from the limit at once (no dead zone to pull back first).
    t = test::move_finger(c, 1, {960.0, 740.0}, {960.0, 686.0}, t + 0.01, 0.01, 6);
    EXPECT_NEAR(c.view().elevation_deg, 51.0, 1e-9);
    // Far up: held at 10.
    test::move_finger(c, 1, {960.0, 686.0}, {960.0, 0.0}, t + 0.01, 0.01, 20);
    EXPECT_DOUBLE_EQ(c.view().elevation_deg, 10.0);
}

TEST(GestureDrag, NewLimitsMoveTheViewInside) {
    GestureController c = test::make_controller(view_at(0.0, 80.0));
    c.set_elevation_limits(-30.0, 45.0);
    EXPECT_DOUBLE_EQ(c.view().elevation_deg, 45.0);
    c.set_elevation_limits(50.0, 70.0);
    EXPECT_DOUBLE_EQ(c.view().elevation_deg, 50.0);
}

TEST(GestureDrag, AzimuthWrapsRoundTheCircle) {
    GestureController c = test::make_controller(view_at(170.0, 0.0));
    // 120 px left: +20 degrees, past 180: 190 is -170.
    test::move_finger(c, 1, {1000.0, 500.0}, {880.0, 500.0}, 1.0, 0.01, 10);
    EXPECT_NEAR(c.view().azimuth_deg, -170.0, 1e-9);
}

TEST(GestureDrag, NoTurnBeforeThePictureSizeIsKnown) {
    GestureController c(GestureOptions{}, view_at(40.0, 30.0));
    test::move_finger(c, 1, {900.0, 500.0}, {1008.0, 600.0}, 1.0, 0.01, 10);
    EXPECT_EQ(c.view().azimuth_deg, 40.0);
    EXPECT_EQ(c.view().elevation_deg, 30.0);
}

}  // namespace
}  // namespace gem::kiosk
