// Energy conservation of the reference render: a colourless stone in a uniform white world
// must come out white, and an absorbing slab seen face-on must give the analytic series.
#include <cmath>

#include <gtest/gtest.h>

#include "cpu/reference_render.hpp"
#include "render_test_stones.hpp"

namespace gem {
namespace {

RenderSettings deep_white_settings(double azimuth, double elevation) {
    RenderSettings s;
    s.width = 24;
    s.height = 24;
    s.samples_per_pixel = 1;
    s.camera = {.azimuth_deg = azimuth, .elevation_deg = elevation};
    s.shading.model = ShadingModel::physical;
    s.trace.max_depth = 200;
    s.trace.min_weight = 1e-12;
    s.trace.weights = WeightModel::fresnel;
    return s;
}

int count_covered(const Image& img) {
    int covered = 0;
    for (const glm::vec4& p : img.pixels) covered += p.w == 1.0f ? 1 : 0;
    return covered;
}

TEST(RenderEnergy, ColourlessCubeFaceOnIsWhite) {
    const Stone cube = render_test::cube(1.0, 1.5);
    const Environment white = Environment::uniform(glm::dvec3(1.0));
    Result<Image> img = render_reference(cube, white, deep_white_settings(0.0, 0.0));
    ASSERT_TRUE(img.ok()) << img.error();
    // The cube spans 1/√3 of the frame (bounding radius √3): about 13 of 24 pixels across.
    EXPECT_GE(count_covered(img.value()), 12 * 12);
    for (const glm::vec4& p : img.value().pixels) {
        if (p.w != 1.0f) continue;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], 1.0, 1e-6);
    }
}

TEST(RenderEnergy, ColourlessCubeObliqueIsWhite) {
    // n = 1.3 < √2, so no ray is trapped in the cube by total internal reflection and the
    // tree ends well inside the depth limit; every covered pixel must add up to 1.
    const Stone cube = render_test::cube(1.0, 1.3);
    const Environment white = Environment::uniform(glm::dvec3(1.0));
    Result<Image> img = render_reference(cube, white, deep_white_settings(33.0, 27.0));
    ASSERT_TRUE(img.ok()) << img.error();
    EXPECT_GT(count_covered(img.value()), 100);
    for (const glm::vec4& p : img.value().pixels) {
        if (p.w != 1.0f) continue;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], 1.0, 1e-6);
    }
}

TEST(RenderEnergy, AbsorbingSlabMatchesTheAnalyticSeries) {
    // Face-on through a cube of side L = 2 mm: a slab at normal incidence. With R the Fresnel
    // reflectance ((n-1)/(n+1))², T = 1 - R and a = exp(-σL), a white world gives
    //   R                                  (front reflection)
    // + T² a / (1 - R² a²)                  (out through the back: T a T, T a R a R a T, ...)
    // + T² R a² / (1 - R² a²)               (back out through the front: T a R a T, ...)
    // summed by hand as geometric series.
    const double n = 1.5;
    const double length = 2.0;
    const glm::dvec3 sigma(0.05, 0.4, 1.5);
    const Stone cube = render_test::cube(0.5 * length, n, sigma);
    const Environment white = Environment::uniform(glm::dvec3(1.0));
    RenderSettings s = deep_white_settings(0.0, 0.0);
    s.width = s.height = 9;
    Result<Image> img = render_reference(cube, white, s);
    ASSERT_TRUE(img.ok()) << img.error();
    const glm::vec4 centre = img.value().at(4, 4);
    ASSERT_EQ(centre.w, 1.0f);
    const double r = ((n - 1.0) / (n + 1.0)) * ((n - 1.0) / (n + 1.0));
    const double t = 1.0 - r;
    for (int c = 0; c < 3; ++c) {
        const double a = std::exp(-sigma[c] * length);
        const double through = t * t * a / (1.0 - r * r * a * a);
        const double back = t * t * r * a * a / (1.0 - r * r * a * a);
        EXPECT_NEAR(centre[c], r + through + back, 1e-6) << "channel " << c;
    }
}

TEST(RenderEnergy, SolidBackgroundAndCoverage) {
    // Off the stone the pixel is the background colour with alpha 0.
    const Stone cube = render_test::cube(1.0, 1.5);
    RenderSettings s = deep_white_settings(0.0, 0.0);
    s.background_is_environment = false;
    s.background_colour = {0.25, 0.5, 0.75};
    Result<Image> img = render_reference(cube, Environment::uniform(glm::dvec3(1.0)), s);
    ASSERT_TRUE(img.ok());
    const glm::vec4 corner = img.value().at(0, 0);
    EXPECT_EQ(corner.w, 0.0f);
    EXPECT_FLOAT_EQ(corner.x, 0.25f);
    EXPECT_FLOAT_EQ(corner.y, 0.5f);
    EXPECT_FLOAT_EQ(corner.z, 0.75f);
}

}  // namespace
}  // namespace gem
