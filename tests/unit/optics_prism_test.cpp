// A prism at minimum deviation, traced with refract(): the deviation must equal the
// textbook value 2·asin(n·sin(A/2)) − A (Born & Wolf, Principles of Optics, §4.7.2) and any
// other incidence must deviate more.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>

#include "optics/fresnel.hpp"

namespace gem {
namespace {

constexpr double kPi = std::numbers::pi;

double radians(double degrees) {
    return degrees * kPi / 180.0;
}

// Unit vector at `angle` from +x in the xy plane.
glm::dvec3 heading(double angle) {
    return {std::cos(angle), std::sin(angle), 0.0};
}

// Prism with its apex up (+y) and apex angle A, in the xy plane. Its faces' outward normals
// point up-left and up-right at A/2 from the horizontal. A ray that crosses it parallel to
// the base meets the entry face at A/2 from the normal, which is the symmetric path.
struct Prism {
    double apex;
    double n;
    glm::dvec3 entry_normal() const { return heading(kPi - apex / 2.0); }  // outward, left
    glm::dvec3 exit_normal() const { return heading(apex / 2.0); }         // outward, right

    // Incidence angle θ1 on the entry face, measured from the inward normal; positive angles
    // aim the ray upward toward the apex. Returns the internal and outgoing directions.
    struct Path {
        glm::dvec3 in, inside, out;
    };
    std::optional<Path> trace(double incidence) const {
        const glm::dvec3 in = heading(-apex / 2.0 + incidence);
        const std::optional<glm::dvec3> inside = refract(in, entry_normal(), 1.0, n);
        if (!inside) return std::nullopt;
        // On the way out the normal passed to refract() must face against the ray: inward.
        const std::optional<glm::dvec3> out = refract(*inside, -exit_normal(), n, 1.0);
        if (!out) return std::nullopt;
        return Path{in, *inside, *out};
    }
};

double deviation(const Prism::Path& p) {
    return std::acos(std::clamp(glm::dot(p.in, p.out), -1.0, 1.0));
}

TEST(OpticsPrism, MinimumDeviationMatchesFormula) {
    // 60° crown glass (BK7, Schott n_d 1.5168), 30° diamond (GIA 2.417) and a 40° moissanite
    // (Nassau et al. 1997, ω = 2.648): n·sin(A/2) < 1 in each, so light gets through.
    const Prism prisms[] = {{radians(60.0), 1.5168},
                            {radians(30.0), 2.417},
                            {radians(40.0), 2.648},
                            {radians(10.0), 1.333}};
    for (const Prism& prism : prisms) {
        const double symmetric_incidence = std::asin(prism.n * std::sin(prism.apex / 2.0));
        const double expected = 2.0 * symmetric_incidence - prism.apex;
        const std::optional<Prism::Path> path = prism.trace(symmetric_incidence);
        ASSERT_TRUE(path.has_value()) << "n = " << prism.n;
        EXPECT_NEAR(deviation(*path), expected, 1e-10) << "n = " << prism.n;
        // At minimum deviation the ray crosses the prism parallel to its base.
        EXPECT_NEAR(path->inside.y, 0.0, 1e-12) << "n = " << prism.n;
        // And the light bends toward the base.
        EXPECT_LT(path->out.y, 0.0);

        for (double offset_deg : {-8.0, -2.0, -0.5, 0.5, 2.0, 8.0}) {
            const std::optional<Prism::Path> other =
                prism.trace(symmetric_incidence + radians(offset_deg));
            if (!other) continue;  // totally reflected at the exit face: no deviation to compare
            EXPECT_GT(deviation(*other), expected + 1e-9)
                << "n = " << prism.n << ", offset " << offset_deg << "°";
        }
    }
}

TEST(OpticsPrism, BlueDeviatesMoreThanRedInGlass) {
    // Schott N-BK7 datasheet: n_F (486.1 nm) = 1.52238, n_C (656.3 nm) = 1.51432.
    const Prism blue{radians(60.0), 1.52238}, red{radians(60.0), 1.51432};
    const double incidence = radians(50.0);
    const auto b = blue.trace(incidence), r = red.trace(incidence);
    ASSERT_TRUE(b && r);
    EXPECT_GT(deviation(*b), deviation(*r));
}

}  // namespace
}  // namespace gem
