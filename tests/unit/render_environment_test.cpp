// Environments: uniform colour, equirectangular lookup (texel centres, bilinear blend, poles),
// image files (PNG decoded from sRGB, Radiance .hdr kept linear) and the studio's character.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "picture/image.hpp"
#include "scene/environment.hpp"

namespace gem {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Unit direction at longitude lon (0 = -z, growing toward +x) and latitude lat.
glm::dvec3 direction(double lon, double lat) {
    return {std::cos(lat) * std::sin(lon), std::sin(lat), -std::cos(lat) * std::cos(lon)};
}

void expect_near(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::path(GEM_ARTIFACT_DIR) / "render_environment_test";
    std::filesystem::create_directories(dir);
    return dir / name;
}

TEST(RenderEnvironment, UniformIsTheSameEverywhere) {
    const Environment env = Environment::uniform({0.2, 0.4, 0.8});
    for (const glm::dvec3& d : {glm::dvec3(0, 1, 0), glm::dvec3(0.6, 0, -0.8)}) {
        expect_near(env.radiance(d), {0.2, 0.4, 0.8}, 0.0);
    }
}

// A 4 × 2 map: texel (i, j) centres at longitude (i + 0.5)/4 · 2π − π and latitude
// π/2 − (j + 0.5)/2 · π, i.e. ±45°.
Environment four_by_two() {
    std::vector<glm::vec3> px;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 4; ++i) px.emplace_back(float(i), float(j), 1.0f);
    }
    return Environment::from_pixels(4, 2, px);
}

TEST(RenderEnvironment, EquirectangularTexelCentresAndBlends) {
    const Environment env = four_by_two();
    const double q = kPi / 4.0;
    // Centre of texel (1, 0): longitude -π/4, latitude +π/4.
    expect_near(env.radiance(direction(-q, q)), {1.0, 0.0, 1.0}, 1e-9);
    // Centre of texel (2, 1): longitude +π/4, latitude -π/4.
    expect_near(env.radiance(direction(q, -q)), {2.0, 1.0, 1.0}, 1e-9);
    // Straight at -z on the equator: halfway between columns 1 and 2 and rows 0 and 1.
    expect_near(env.radiance({0.0, 0.0, -1.0}), {1.5, 0.5, 1.0}, 1e-9);
    // Longitude π wraps: halfway between column 3 and column 0.
    expect_near(env.radiance(direction(kPi - 1e-12, q)), {1.5, 0.0, 1.0}, 1e-6);
    // Above the top row's centres the rows clamp to the top row.
    expect_near(env.radiance(direction(-q, 1.4)), {1.0, 0.0, 1.0}, 1e-9);
}

TEST(RenderEnvironment, PngIsDecodedFromSrgb) {
    Image img(4, 2, glm::vec4(0.18f, 0.5f, 1.0f, 1.0f));
    const auto path = scratch("env.png");
    ASSERT_TRUE(write_png(img, path).ok());
    Result<Environment> env = Environment::load_image(path);
    ASSERT_TRUE(env.ok()) << env.error();
    // 8-bit quantisation of sRGB moves the value by at most half a code: < 0.3 % here.
    expect_near(env.value().radiance({0, 0, -1}), {0.18, 0.5, 1.0}, 0.003);
}

TEST(RenderEnvironment, RadianceHdrIsLinear) {
    // Radiance RGBE, flat scanlines (width < 8 is never run-length encoded): (128,128,128,129)
    // is 128/256 · 2^(129-128) = 1.0 and (192,64,128,128) is (0.75, 0.25, 0.5).
    const auto path = scratch("env.hdr");
    {
        std::ofstream out(path, std::ios::binary);
        out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n";
        const unsigned char px[16] = {128, 128, 128, 129, 128, 128, 128, 129,
                                      192, 64,  128, 128, 192, 64,  128, 128};
        out.write(reinterpret_cast<const char*>(px), 16);
    }
    Result<Environment> env = Environment::load_image(path);
    ASSERT_TRUE(env.ok()) << env.error();
    expect_near(env.value().radiance({0, 1, 0}), {1.0, 1.0, 1.0}, 1e-6);
    expect_near(env.value().radiance({0, -1, 0}), {0.75, 0.25, 0.5}, 1e-6);
}

TEST(RenderEnvironment, BadImageIsAnErrorNamingTheFile) {
    const auto path = scratch("not-an-image.png");
    std::ofstream(path) << "hello";
    Result<Environment> env = Environment::load_image(path);
    ASSERT_FALSE(env.ok());
    EXPECT_NE(env.error().find("not-an-image.png"), std::string::npos) << env.error();
    Result<Environment> missing = Environment::load_image(scratch("missing.hdr"));
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("missing.hdr"), std::string::npos) << missing.error();
}

TEST(RenderEnvironment, StudioIsDarkBelowWithBrightLightsAbove) {
    const Environment env = Environment::studio();
    double brightest_above = 0.0;
    double brightest_below = 0.0;
    for (int i = 0; i < 72; ++i) {
        for (int j = 1; j < 18; ++j) {
            const double lon = i * kPi / 36.0;
            const double lat = j * kPi / 36.0;  // 5° .. 85°
            const glm::dvec3 up = env.radiance(direction(lon, lat));
            const glm::dvec3 down = env.radiance(direction(lon, -lat));
            for (const glm::dvec3& c : {up, down}) {
                ASSERT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
                ASSERT_GE(std::min({c.x, c.y, c.z}), 0.0);
            }
            brightest_above = std::max(brightest_above, up.y);
            brightest_below = std::max(brightest_below, down.y);
        }
    }
    EXPECT_GT(brightest_above, 2.0);   // softboxes
    EXPECT_LT(brightest_below, 0.05);  // the counter
    // Deterministic: the same direction gives the same value.
    EXPECT_EQ(env.radiance(direction(0.3, 0.9)),
              Environment::studio().radiance(direction(0.3, 0.9)));
}

TEST(RenderEnvironment, TheLightTentIsWhiteWithDarkFlagsWhereTheyStand) {
    const Environment tent = Environment::light_tent();
    // Azimuth from +z toward +x, elevation above the girdle plane (environment_tent.cpp's
    // convention, the camera's).
    const auto at = [&](double azimuth_deg, double elevation_deg) {
        const double a = azimuth_deg * kPi / 180.0, e = elevation_deg * kPi / 180.0;
        return tent.radiance({std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)});
    };
    // Inside the flags at 0° (±14°, -15° to 50°) and 60° (±10°, -10° to 35°).
    EXPECT_LT(at(0.0, 20.0).x, 0.05);
    EXPECT_LT(at(60.0, 10.0).x, 0.05);
    EXPECT_LT(at(180.0 + 60.0, 20.0).x, 0.05);
    // Between them, the wall (0.8); overhead, twice as bright; below the flags, the sweep.
    EXPECT_NEAR(at(30.0, 10.0).x, 0.8, 0.02);
    EXPECT_NEAR(at(0.0, 89.0).x, 1.6, 0.02);
    EXPECT_GT(at(0.0, -60.0).x, 0.5);
    // Grey: every channel alike.
    EXPECT_EQ(at(30.0, 10.0).x, at(30.0, 10.0).z);
}

}  // namespace
}  // namespace gem

TEST(Environment, WithIntensityScalesEveryRadiance) {
    // A lighting preset's environment level multiplies what every direction sends; applying
    // two levels multiplies them.
    const gem::Environment studio = gem::Environment::studio();
    const gem::Environment dimmer = studio.with_intensity(0.25).with_intensity(2.0);
    for (const glm::dvec3 d : {glm::dvec3(0, 1, 0), glm::dvec3(0.6, 0.0, 0.8), glm::dvec3(0, -1, 0),
                               glm::dvec3(-0.48, 0.6, -0.64)}) {
        const glm::dvec3 expected = studio.radiance(d) * 0.5;
        EXPECT_NEAR(dimmer.radiance(d).x, expected.x, 1e-12);
        EXPECT_NEAR(dimmer.radiance(d).y, expected.y, 1e-12);
        EXPECT_NEAR(dimmer.radiance(d).z, expected.z, 1e-12);
    }
    EXPECT_EQ(gem::Environment::uniform({1, 2, 3}).with_intensity(3.0).radiance({0, 0, 1}),
              glm::dvec3(3, 6, 9));
}

TEST(Environment, MeanRadianceIsTheAverageOverTheSphere) {
    // A uniform sky is its colour everywhere; an image bright above the horizon and black
    // below sends half its brightness on average (each hemisphere is half the sphere), and a
    // band of the top sixth of its rows (above latitude 60°) sends (1 - sin 60°) / 2 of it.
    const glm::dvec3 uniform = gem::Environment::uniform({0.2, 0.4, 0.8}).mean_radiance();
    EXPECT_NEAR(uniform.x, 0.2, 1e-12);
    EXPECT_NEAR(uniform.z, 0.8, 1e-12);
    const int w = 64, h = 96;
    std::vector<glm::vec3> upper(w * h, glm::vec3(0.0f)), cap(w * h, glm::vec3(0.0f));
    for (int y = 0; y < h / 2; ++y) {
        for (int x = 0; x < w; ++x) upper[y * w + x] = glm::vec3(1.0f);
    }
    for (int y = 0; y < h / 6; ++y) {
        for (int x = 0; x < w; ++x) cap[y * w + x] = glm::vec3(1.0f);
    }
    EXPECT_NEAR(gem::Environment::from_pixels(w, h, upper).mean_radiance().y, 0.5, 2e-3);
    EXPECT_NEAR(gem::Environment::from_pixels(w, h, cap).mean_radiance().y,
                (1.0 - std::sqrt(3.0) / 2.0) / 2.0, 3e-3);
}
