// Image error: CIEDE2000 against the published test pairs, CIELAB of sRGB codes against
// their known values, and the image statistics against hand calculations.
#include <gtest/gtest.h>

#include <cmath>

#include "picture/image_error.hpp"

namespace gem {
namespace {

struct Pair {
    Lab x, y;
    double delta_e;
};

// Sharma, Wu and Dalal, "The CIEDE2000 color-difference formula: implementation notes,
// supplementary test data, and mathematical observations", Color Res. Appl. 30(1), 2005,
// Table 1, pairs 1, 7, 17 and 25 (they exercise the hue-angle and mean-hue branches).
TEST(ImageError, Ciede2000MatchesSharmaTestData) {
    const Pair pairs[] = {
        {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},
        {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
        {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
        {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
    };
    for (const Pair& p : pairs) {
        EXPECT_NEAR(ciede2000(p.x, p.y), p.delta_e, 1e-4);
        EXPECT_NEAR(ciede2000(p.y, p.x), p.delta_e, 1e-4);  // symmetric
    }
}

TEST(ImageError, LabOfSrgbCodes) {
    const Lab white = srgb8_to_lab(255, 255, 255);
    EXPECT_NEAR(white.l, 100.0, 1e-3);
    EXPECT_NEAR(white.a, 0.0, 1e-3);
    EXPECT_NEAR(white.b, 0.0, 1e-3);
    // sRGB red: CIELAB (53.24, 80.09, 67.20) under D65 (the usual published conversion).
    const Lab red = srgb8_to_lab(255, 0, 0);
    EXPECT_NEAR(red.l, 53.24, 0.05);
    EXPECT_NEAR(red.a, 80.09, 0.1);
    EXPECT_NEAR(red.b, 67.20, 0.1);
    // Code 119 is linear 0.1845 (IEC 61966-2-1), L* = 116·0.1845^(1/3) − 16 = 50.04.
    EXPECT_NEAR(srgb8_to_lab(119, 119, 119).l, 116.0 * std::cbrt(0.18447) - 16.0, 0.02);
}

Image grey(int w, int h, float alpha = 1.0f) {
    const float linear = 0.18447f;  // sRGB code 119
    return Image(w, h, glm::vec4(linear, linear, linear, alpha));
}

TEST(ImageError, IdenticalImagesHaveNoError) {
    const auto e = compare_images(grey(8, 8), grey(8, 8));
    ASSERT_TRUE(e.ok()) << e.error();
    EXPECT_TRUE(std::isinf(e.value().psnr_db));
    EXPECT_EQ(e.value().delta_e_mean, 0.0);
    EXPECT_EQ(e.value().share_visible, 0.0);
    EXPECT_EQ(e.value().pixels, 64u);
}

TEST(ImageError, OneWhitePixelAgainstHandCalculation) {
    Image test = grey(10, 10);
    test.at(3, 4) = glm::vec4(1.0f);
    const auto e = compare_images(test, grey(10, 10));
    ASSERT_TRUE(e.ok()) << e.error();
    // PSNR: one pixel of 100 off by 255 − 119 = 136 in each of 3 channels.
    const double mse = 3.0 * 136.0 * 136.0 / 300.0;
    EXPECT_NEAR(e.value().psnr_db, 10.0 * std::log10(255.0 * 255.0 / mse), 1e-9);
    // ΔE00 of two neutral greys is the lightness term alone: ΔL / S_L, with
    // S_L = 1 + 0.015 (L̄ − 50)² / √(20 + (L̄ − 50)²) (CIE 142-2001).
    const double l1 = 116.0 * std::cbrt(0.18447) - 16.0, l2 = 100.0;
    const double m = (l1 + l2) / 2.0 - 50.0;
    const double expected = (l2 - l1) / (1.0 + 0.015 * m * m / std::sqrt(20.0 + m * m));
    EXPECT_NEAR(e.value().delta_e_max, expected, 0.05);
    EXPECT_NEAR(e.value().delta_e_mean, expected / 100.0, 0.001);
    EXPECT_DOUBLE_EQ(e.value().share_visible, 0.01);
    EXPECT_EQ(e.value().delta_e_p99, 0.0);  // 99 of 100 pixels are exact
}

TEST(ImageError, OnlyStoneLeavesTheBackgroundOut) {
    Image test = grey(10, 10, 0.0f), reference = grey(10, 10, 0.0f);
    test.at(0, 0) = glm::vec4(1.0f, 1.0f, 1.0f, 0.0f);  // off the stone in both: ignored
    for (int x = 0; x < 5; ++x) test.at(x, 9).w = reference.at(x, 9).w = 1.0f;
    test.at(1, 9) = glm::vec4(1.0f);  // on the stone
    ErrorOptions options;
    options.only_stone = true;
    const auto e = compare_images(test, reference, options);
    ASSERT_TRUE(e.ok()) << e.error();
    EXPECT_EQ(e.value().pixels, 5u);
    EXPECT_DOUBLE_EQ(e.value().share_visible, 0.2);
}

TEST(ImageError, RefusesMismatchedSizes) {
    const auto e = compare_images(grey(4, 4), grey(4, 5));
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().find("sizes differ"), std::string::npos);
    EXPECT_TRUE(delta_e_map(grey(4, 4), grey(5, 4)).empty());
}

TEST(ImageError, HeatMapRunsBlackToWhite) {
    const Image map = heat_map({0.0f, 5.0f, 10.0f, 20.0f}, 2, 2, 10.0f);
    EXPECT_EQ(map.pixels[0], glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_NEAR(map.pixels[2].x, 1.0f, 1e-6);
    EXPECT_NEAR(map.pixels[2].z, 1.0f, 1e-6);
    EXPECT_EQ(map.pixels[3], map.pixels[2]);      // clipped at full scale
    EXPECT_GT(map.pixels[1].x, map.pixels[1].z);  // halfway is red-yellow, not white
}

}  // namespace
}  // namespace gem
