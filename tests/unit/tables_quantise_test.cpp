// Quantisation error bounds: measured worst cases against the bounds derived in
// gemdb/quantise.hpp, and exact half-float codes worked out by hand from IEEE 754.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "gemdb/quantise.hpp"
#include "tables_test_support.hpp"

namespace gem {
namespace {

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

TEST(TablesQuantise, OctahedralBoundIsHandDerivedValue) {
    // √18 / 65535, the bound derived in the header, worked out independently.
    EXPECT_NEAR(kOctahedralMaxAngle, std::sqrt(18.0) / 65535.0, 1e-18);
}

TEST(TablesQuantise, OctahedralErrorWithinBoundAndBoundIsTight) {
    std::mt19937_64 rng(42);
    double worst = 0.0;
    for (int i = 0; i < 1'000'000; ++i) {
        const glm::dvec3 d = tables_test::random_unit(rng);
        worst = std::max(worst, angle_between(d, decode_octahedral(encode_octahedral(d))));
    }
    EXPECT_LE(worst, kOctahedralMaxAngle);
    // The bound is reached only at a face centre with a half step in both codes; random
    // directions come within a factor of two of it.
    EXPECT_GE(worst, 0.5 * kOctahedralMaxAngle) << "bound is needlessly loose";
    RecordProperty("octahedral_max_angle_rad", std::to_string(worst));
}

TEST(TablesQuantise, OctahedralWorstCaseNearFaceCentre) {
    // Directions around (1,1,1)/√3, where the projection stretches most, sampled densely.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-2e-4, 2e-4);
    double worst = 0.0;
    for (int i = 0; i < 200'000; ++i) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(1.0 + jitter(rng), 1.0 + jitter(rng), 1.0));
        worst = std::max(worst, angle_between(d, decode_octahedral(encode_octahedral(d))));
    }
    EXPECT_LE(worst, kOctahedralMaxAngle);
    EXPECT_GE(worst, 0.9 * kOctahedralMaxAngle);
}

TEST(TablesQuantise, OctahedralAxesAndLowerHemisphere) {
    for (const glm::dvec3 d :
         {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0),
          glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::normalize(glm::dvec3(-1, -1, -1)),
          glm::normalize(glm::dvec3(0.3, -0.2, -5))}) {
        EXPECT_LE(angle_between(d, decode_octahedral(encode_octahedral(d))), kOctahedralMaxAngle)
            << d.x << " " << d.y << " " << d.z;
    }
    // Length does not matter, only direction.
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.2, -0.7, 0.1));
    const OctCode a = encode_octahedral(d);
    const OctCode b = encode_octahedral(13.0 * d);
    EXPECT_EQ(a.u, b.u);
    EXPECT_EQ(a.v, b.v);
}

TEST(TablesQuantise, HalfCodesWorkedOutByHand) {
    EXPECT_EQ(float_to_half(1.0f), 0x3C00);   // exponent 15, mantissa 0
    EXPECT_EQ(float_to_half(-2.0f), 0xC000);  // sign, exponent 16
    EXPECT_EQ(float_to_half(0.0f), 0x0000);
    EXPECT_EQ(float_to_half(-0.0f), 0x8000);
    EXPECT_EQ(float_to_half(65504.0f), 0x7BFF);               // largest finite half
    EXPECT_EQ(float_to_half(65519.0f), 0x7BFF);               // below the halfway point to 65536
    EXPECT_EQ(float_to_half(65520.0f), 0x7C00);               // halfway, rounds to even = infinity
    EXPECT_EQ(float_to_half(std::ldexp(1.0f, -14)), 0x0400);  // smallest normal
    EXPECT_EQ(float_to_half(std::ldexp(1.0f, -24)), 0x0001);  // smallest subnormal
    EXPECT_EQ(float_to_half(std::ldexp(1.0f, -25)), 0x0000);  // halfway to 0: even
    EXPECT_EQ(float_to_half(std::ldexp(3.0f, -26)), 0x0001);  // 0.75 of a step: up
    EXPECT_EQ(float_to_half(std::ldexp(3.0f, -25)), 0x0002);  // 1.5 steps: tie to even 2
    EXPECT_EQ(float_to_half(1.0f + std::ldexp(1.0f, -11)), 0x3C00);         // tie, even down
    EXPECT_EQ(float_to_half(1.0f + 3.0f * std::ldexp(1.0f, -11)), 0x3C02);  // tie, even up
    EXPECT_EQ(float_to_half(0.1f), 0x2E66);  // 0.1 = 1.6·2^-4: mantissa 0.6·1024 = 614.4 → 614
    EXPECT_EQ(float_to_half(std::numeric_limits<float>::infinity()), 0x7C00);
    EXPECT_EQ(float_to_half(1e-30f), 0x0000);
    EXPECT_TRUE(std::isnan(half_to_float(float_to_half(std::numeric_limits<float>::quiet_NaN()))));
    // 0x3555: exponent 13, mantissa 341 → (1 + 341/1024) · 2^-2.
    EXPECT_EQ(half_to_float(0x3555), 0.333251953125f);
    EXPECT_EQ(half_to_float(0x0001), std::ldexp(1.0f, -24));
    EXPECT_EQ(half_to_float(0xFBFF), -65504.0f);
}

TEST(TablesQuantise, EveryHalfSurvivesARoundTrip) {
    for (std::uint32_t h = 0; h <= 0xFFFF; ++h) {
        const bool nan = (h & 0x7C00) == 0x7C00 && (h & 0x3FF) != 0;
        if (nan) continue;
        ASSERT_EQ(float_to_half(half_to_float(static_cast<std::uint16_t>(h))), h);
    }
}

TEST(TablesQuantise, HalfRelativeErrorWithinBound) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> exponent(-14.0, std::log2(kHalfMaxValue));
    double worst = 0.0;
    for (int i = 0; i < 1'000'000; ++i) {
        const double x = std::exp2(exponent(rng));
        const double back = half_to_float(double_to_half(x));
        worst = std::max(worst, std::abs(back - x) / x);
    }
    // Double → float adds at most 2^-24 relative before the half rounding.
    EXPECT_LE(worst, kHalfMaxRelativeError * (1.0 + std::ldexp(1.0, -23)));
    EXPECT_GE(worst, 0.99 * kHalfMaxRelativeError);
    std::uniform_real_distribution<double> tiny(0.0, kHalfMinNormal);
    double worst_abs = 0.0;
    for (int i = 0; i < 100'000; ++i) {
        const double x = tiny(rng);
        worst_abs = std::max(worst_abs, std::abs(half_to_float(double_to_half(x)) - x));
    }
    // Double → float first rounds by up to 2^-24 of the value (< 2^-14).
    EXPECT_LE(worst_abs, kHalfMaxSubnormalError + kHalfMinNormal * std::ldexp(1.0, -24));
    EXPECT_GE(worst_abs, 0.99 * kHalfMaxSubnormalError);
}

TEST(TablesQuantise, PositionErrorWithinHalfAStep) {
    const PositionBox box{{-3.0, -1.5, -2.0}, {3.0, 1.5, 2.0}};
    const glm::dvec3 bound = glm::dvec3(6.0, 3.0, 4.0) / 65535.0 / 2.0;  // extent / 65535 / 2
    EXPECT_NEAR(box.max_error().x, bound.x, 1e-18);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    glm::dvec3 worst(0.0);
    for (int i = 0; i < 300'000; ++i) {
        const glm::dvec3 p =
            box.min + glm::dvec3(unit(rng), unit(rng), unit(rng)) * (box.max - box.min);
        worst = glm::max(worst, glm::abs(decode_position(encode_position(p, box), box) - p));
    }
    for (int a = 0; a < 3; ++a) {
        EXPECT_LE(worst[a], bound[a] * (1.0 + 1e-9)) << "axis " << a;
        EXPECT_GE(worst[a], 0.99 * bound[a]) << "axis " << a;
    }
    // Outside the box, positions clamp onto it.
    const glm::dvec3 outside = decode_position(encode_position({9.0, -9.0, 0.0}, box), box);
    EXPECT_DOUBLE_EQ(outside.x, 3.0);
    EXPECT_DOUBLE_EQ(outside.y, -1.5);
}

}  // namespace
}  // namespace gem
