// The finger-motion estimate between two frames, checked against rigid motions built by hand.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gestures/contact_motion.hpp"

namespace gem::kiosk {
namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// `p` turned by `degrees` (clockwise on screen, y down) and scaled by `scale` about `centre`.
glm::dvec2 turned(glm::dvec2 p, glm::dvec2 centre, double degrees, double scale) {
    const double a = degrees * kRadiansPerDegree;
    const glm::dvec2 d = p - centre;
    return centre + scale * glm::dvec2(d.x * std::cos(a) - d.y * std::sin(a),
                                       d.x * std::sin(a) + d.y * std::cos(a));
}

TEST(ContactMotion, ThreeFingersTurnedAndScaledRigidly) {
    const std::vector<glm::dvec2> points = {{100.0, 200.0}, {400.0, 260.0}, {250.0, 500.0}};
    const glm::dvec2 centroid = (points[0] + points[1] + points[2]) / 3.0;
    const glm::dvec2 shift(35.0, -12.0);
    std::vector<Contact> before;
    std::vector<Contact> after;
    for (int i = 0; i < 3; ++i) {
        before.push_back({10 + i, points[i]});
        // Listed in another order: fingers are matched by id, not by place in the list.
        after.insert(after.begin(),
                     Contact{10 + i, turned(points[i], centroid, 25.0, 1.3) + shift});
    }
    const ContactMotion m = contact_motion(before, after, 8.0);
    EXPECT_EQ(m.common, 3);
    EXPECT_TRUE(m.spread_measurable);
    EXPECT_NEAR(m.scale, 1.3, 1e-12);
    EXPECT_NEAR(m.rotation_deg, 25.0, 1e-9);
    EXPECT_NEAR(m.translation.x, shift.x, 1e-9);
    EXPECT_NEAR(m.translation.y, shift.y, 1e-9);
}

TEST(ContactMotion, FingersInOnlyOneFrameTakeNoPart) {
    const std::vector<Contact> before = {{1, {100.0, 100.0}}, {2, {300.0, 100.0}}};
    const std::vector<Contact> after = {
        {1, {100.0, 100.0}}, {2, {300.0, 100.0}}, {3, {900.0, 900.0}}};
    const ContactMotion m = contact_motion(before, after, 8.0);
    EXPECT_EQ(m.common, 2);
    EXPECT_DOUBLE_EQ(m.scale, 1.0);
    EXPECT_DOUBLE_EQ(m.rotation_deg, 0.0);
    EXPECT_DOUBLE_EQ(m.translation.x, 0.0);
    EXPECT_DOUBLE_EQ(m.translation.y, 0.0);
}

TEST(ContactMotion, OneFingerGivesOnlyItsMove) {
    const ContactMotion m =
        contact_motion({{7, {10.0, 20.0}}}, {{7, {13.0, 16.0}}, {8, {0.0, 0.0}}}, 8.0);
    EXPECT_EQ(m.common, 1);
    EXPECT_FALSE(m.spread_measurable);
    EXPECT_DOUBLE_EQ(m.translation.x, 3.0);
    EXPECT_DOUBLE_EQ(m.translation.y, -4.0);
}

TEST(ContactMotion, FingersTooCloseGiveNoScale) {
    // 10 px apart: 5 px from their midpoint, under the 8 px asked for.
    const ContactMotion m = contact_motion({{1, {100.0, 100.0}}, {2, {110.0, 100.0}}},
                                           {{1, {100.0, 100.0}}, {2, {100.0, 110.0}}}, 8.0);
    EXPECT_FALSE(m.spread_measurable);
    EXPECT_EQ(m.scale, 1.0);
    EXPECT_EQ(m.rotation_deg, 0.0);
}

}  // namespace
}  // namespace gem::kiosk
