// The display transform (picture/tone_map.hpp): values worked by hand from the PBR Neutral
// specification's formulas, the properties the curve is chosen for (hue kept, nothing above 1,
// order kept), and the exposure.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "picture/tone_map.hpp"

namespace gem {
namespace {

// HSV hue in degrees of a colour with distinct channels (the textbook hexcone formula).
double hue_deg(const glm::dvec3& c) {
    const double hi = std::max({c.x, c.y, c.z});
    const double lo = std::min({c.x, c.y, c.z});
    const double span = hi - lo;
    double h = 0.0;
    if (hi == c.x) {
        h = std::fmod((c.y - c.z) / span, 6.0);
    } else if (hi == c.y) {
        h = (c.z - c.x) / span + 2.0;
    } else {
        h = (c.x - c.y) / span + 4.0;
    }
    h *= 60.0;
    return h < 0.0 ? h + 360.0 : h;
}

const DisplayTransform kNeutral{ToneCurve::neutral, 0.0};
const DisplayTransform kClip{ToneCurve::clip, 0.0};

TEST(ToneMap, BelowTheKneeOnlyTheSmallOffsetIsTaken) {
    // min = 0.2 > 2 F90, so f = 0.04; the peak 0.46 is below K_s = 0.76: c - f.
    const glm::dvec3 out = to_display({0.5, 0.3, 0.2}, kNeutral);
    EXPECT_NEAR(out.x, 0.46, 1e-12);
    EXPECT_NEAR(out.y, 0.26, 1e-12);
    EXPECT_NEAR(out.z, 0.16, 1e-12);
    // A dark grey: min = 0.05 <= 0.08, f = 0.05 - 0.05^2 / 0.16 = 0.034375.
    const glm::dvec3 dark = to_display(glm::dvec3(0.05), kNeutral);
    EXPECT_NEAR(dark.x, 0.05 - 0.034375, 1e-12);
    EXPECT_EQ(to_display(glm::dvec3(0.0), kNeutral), glm::dvec3(0.0));
}

TEST(ToneMap, AHighlightIsCompressedAsTheFormulaSays) {
    // Grey 2: f = 0.04, p = 1.96, p_n = 1 - 0.24^2 / (1.96 + 1 - 1.52) = 1 - 0.0576 / 1.44
    // = 0.96; grey stays grey, so the result is p_n whatever g is.
    const glm::dvec3 out = to_display(glm::dvec3(2.0), kNeutral);
    EXPECT_NEAR(out.x, 0.96, 1e-12);
    EXPECT_NEAR(out.y, 0.96, 1e-12);
    // (3, 1, 0.5): f = 0.04, p = 2.96, p_n = 1 - 0.0576 / 2.44, g = 1 / (0.15 (p - p_n) + 1).
    const double pn = 1.0 - 0.0576 / 2.44;
    const double g = 1.0 / (0.15 * (2.96 - pn) + 1.0);
    const glm::dvec3 c = to_display({3.0, 1.0, 0.5}, kNeutral);
    EXPECT_NEAR(c.x, 2.96 * pn / 2.96 * g + pn * (1.0 - g), 1e-12);
    EXPECT_NEAR(c.y, 0.96 * pn / 2.96 * g + pn * (1.0 - g), 1e-12);
    EXPECT_NEAR(c.z, 0.46 * pn / 2.96 * g + pn * (1.0 - g), 1e-12);
}

TEST(ToneMap, ContinuousAtTheKnee) {
    // Peak exactly K_s + f after the offset: both branches give the same value.
    const double k = 0.76 + 0.04;
    const glm::dvec3 below = to_display({k - 1e-9, 0.5, 0.3}, kNeutral);
    const glm::dvec3 above = to_display({k + 1e-9, 0.5, 0.3}, kNeutral);
    EXPECT_NEAR(below.x, above.x, 1e-8);
    EXPECT_NEAR(below.y, above.y, 1e-8);
}

TEST(ToneMap, BrightColoursKeepTheirHueWhereAClipDoesNot) {
    // An orange flash of fire, 1x to 50x over the display's white.
    const glm::dvec3 orange(1.0, 0.45, 0.1);
    for (double scale : {1.5, 4.0, 12.0, 50.0}) {
        const glm::dvec3 in = orange * scale;
        const glm::dvec3 out = to_display(in, kNeutral);
        EXPECT_NEAR(hue_deg(out), hue_deg(in), 1e-6) << scale;
        EXPECT_LE(std::max({out.x, out.y, out.z}), 1.0);
    }
    // Clipped, the same flash turns yellow (its red and green both cut at 1).
    EXPECT_GT(std::abs(hue_deg(to_display(orange * 4.0, kClip)) - hue_deg(orange)), 10.0);
}

TEST(ToneMap, BrighterInputIsNeverDarkerAndStaysBelowOne) {
    double last = -1.0;
    for (double v = 0.0; v < 1000.0; v = v * 1.1 + 0.001) {
        const double out = to_display(glm::dvec3(v, 0.6 * v, 0.2 * v), kNeutral).x;
        EXPECT_GE(out, last - 1e-12) << v;
        EXPECT_LE(out, 1.0);
        last = out;
    }
    EXPECT_GT(last, 0.999);
}

TEST(ToneMap, ExposureScalesTheInputByPowersOfTwo) {
    const glm::dvec3 c(0.3, 0.2, 0.1);
    EXPECT_EQ(to_display(c, {ToneCurve::neutral, 1.0}), to_display(2.0 * c, kNeutral));
    EXPECT_EQ(to_display(c, {ToneCurve::clip, -2.0}), to_display(0.25 * c, kClip));
    EXPECT_EQ(to_display(glm::dvec3(-1.0, 2.0, 0.5), kClip), glm::dvec3(0.0, 1.0, 0.5));
}

// The IEC 61966-2-1 transfer function, written out here apart from optics/colour.cpp.
double srgb(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}
double linear(double e) {
    return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

TEST(ToneMap, AnUnseenChangeIsHalfACodeOnTheSteeperSideForTheClip) {
    // Grey: each channel alone, through the clip curve at 0 EV, moves half a code at a change
    // of its linear value that the inverse transfer gives; the darker side is the steeper.
    for (const double v : {0.002, 0.03, 0.2, 0.7}) {
        const double code = 255.0 * srgb(v);
        const double down = v - linear((code - 0.5) / 255.0);
        const double up = linear((code + 0.5) / 255.0) - v;
        const double expected = 0.75 * std::min(down, up);
        EXPECT_NEAR(unseen_change(glm::dvec3(v), kClip), expected, 1e-3 * expected) << v;
    }
}

TEST(ToneMap, AnUnseenChangeMovesNoCodeByHalfAndTwiceItDoes) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const auto codes = [](const glm::dvec3& c, const DisplayTransform& t) {
        const glm::dvec3 d = to_display(c, t);
        return 255.0 * glm::dvec3(srgb(d.x), srgb(d.y), srgb(d.z));
    };
    for (const DisplayTransform& t : {kNeutral, DisplayTransform{ToneCurve::neutral, 1.5}}) {
        for (const glm::dvec3 c : {glm::dvec3(0.02, 0.03, 0.05), glm::dvec3(0.3, 0.2, 0.1),
                                   glm::dvec3(0.9, 0.95, 1.0), glm::dvec3(3.0, 2.0, 1.0)}) {
            const double change = unseen_change(c, t);
            ASSERT_GT(change, 0.0);
            const glm::dvec3 at = codes(c, t);
            double most = 0.0;
            for (int i = 0; i < 4000; ++i) {
                const glm::dvec3 step(unit(random), unit(random), unit(random));
                const glm::dvec3 moved = glm::abs(codes(c + change * step, t) - at);
                most = std::max({most, moved.x, moved.y, moved.z});
            }
            EXPECT_LT(most, 0.5) << c.x << " " << c.y << " " << c.z;
            // Not needlessly small: some change of at most three times as much is seen.
            double seen = 0.0;
            for (int i = 0; i < 4000; ++i) {
                const glm::dvec3 step(unit(random), unit(random), unit(random));
                const glm::dvec3 moved = glm::abs(codes(c + 3.0 * change * step, t) - at);
                seen = std::max({seen, moved.x, moved.y, moved.z});
            }
            EXPECT_GE(seen, 0.5) << c.x << " " << c.y << " " << c.z;
        }
    }
}

TEST(ToneMap, NamesRoundTrip) {
    for (ToneCurve c : {ToneCurve::clip, ToneCurve::neutral}) {
        EXPECT_EQ(tone_curve_named(to_string(c)), c);
    }
    EXPECT_FALSE(tone_curve_named("filmic").has_value());
}

}  // namespace
}  // namespace gem
