// The view's turn rate (stage/turn_rate.hpp) against the rotation it was given: a direction
// turned by θ about +y in dt seconds is a turn of sin θ / dt about +y (|a × b| = sin θ for unit
// vectors, along the axis they turn about).
#include <gtest/gtest.h>

#include <cmath>

#include "stage/turn_rate.hpp"

namespace gem::kiosk {
namespace {

glm::dvec3 turned_about_y(const glm::dvec3& v, double angle) {
    return {std::cos(angle) * v.x + std::sin(angle) * v.z, v.y,
            -std::sin(angle) * v.x + std::cos(angle) * v.z};
}

TEST(TurnRate, ADirectionTurnedAboutTheVerticalIsATurnAboutIt) {
    TurnRate rate;
    const glm::dvec3 start = glm::normalize(glm::dvec3(0.3, -0.5, -0.8));
    EXPECT_EQ(rate.next(start, 10.0), glm::dvec3(0.0));  // nothing to turn from yet
    const double angle = 0.05, dt = 1.0 / 60.0;
    const glm::dvec3 omega = rate.next(turned_about_y(start, angle), 10.0 + dt);
    // The part of the direction in the turn's plane is what turns: its length squared times
    // sin θ, here 1 − y².
    const double expected = (1.0 - start.y * start.y) * std::sin(angle) / dt;
    EXPECT_NEAR(omega.y, expected, 1e-9);
    // About +y alone, to the component the direction's tilt adds (it is not turned about x, z).
    EXPECT_NEAR(glm::length(glm::dvec3(omega.x, 0.0, omega.z)),
                std::abs(start.y) * std::sqrt(1.0 - start.y * start.y) *
                    std::sqrt(2.0 - 2.0 * std::cos(angle)) / dt,
                1e-9);
}

TEST(TurnRate, NoTimeBetweenAndARestartTurnNothing) {
    TurnRate rate;
    const glm::dvec3 a(0.0, 0.0, -1.0);
    const glm::dvec3 b = turned_about_y(a, 0.1);
    rate.next(a, 1.0);
    EXPECT_EQ(rate.next(b, 1.0), glm::dvec3(0.0));
    rate.restart();
    EXPECT_EQ(rate.next(a, 2.0), glm::dvec3(0.0));
    EXPECT_GT(std::abs(rate.next(b, 2.5).y), 0.0);
}

}  // namespace
}  // namespace gem::kiosk
