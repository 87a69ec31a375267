// Edges and vertices of a real cut on the CPU. Rays aimed exactly at every vertex and at the
// middle of every facet edge of a round brilliant, and one ulp either side in each coordinate,
// must come out finite, conserve energy, leave and obey Snell (failure_optics_ray_checks.hpp).
// Then the CPU reference image in a uniform white surround: with no absorption and no lights
// a pixel's colour is the light that left the stone, 1 − truncated, so a black pixel inside
// the stone could only be a lost ray; partial coverage at the silhouette is the one
// geometric reason for a darker pixel, and those pixels are left out by their alpha.

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <set>

#include "cpu/reference_render.hpp"
#include "failure_optics_ray_checks.hpp"
#include "trace_test_stones.hpp"

namespace gem {
namespace {

constexpr double kDiamond = 2.417;  // GIA Gem Reference Guide, 1995

TEST(FailureOpticsEdges, RaysAtEveryVertexAndEdgeOfABrilliantStayClean) {
    const Stone stone = failure_test::round_brilliant(kDiamond);
    ASSERT_FALSE(stone.facets.empty());
    std::vector<glm::dvec3> targets;
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const Facet& f : stone.facets) {
        for (std::size_t i = 0; i < f.loop.size(); ++i) {
            edges.insert(std::minmax(f.loop[i], f.loop[(i + 1) % f.loop.size()]));
        }
    }
    for (const glm::dvec3& v : stone.vertices) {
        for (const glm::dvec3& t : failure_test::ulp_neighbourhood(v)) targets.push_back(t);
    }
    for (const auto& [a, b] : edges) {
        const glm::dvec3 mid = 0.5 * (stone.vertices[a] + stone.vertices[b]);
        for (const glm::dvec3& t : failure_test::ulp_neighbourhood(mid)) targets.push_back(t);
    }
    const Tracer tracer(stone);
    const auto surface = make_intersector(stone);
    std::mt19937_64 rng(71);
    failure_test::RayCheck check;
    for (const glm::dvec3& target : targets) {
        for (int i = 0; i < 2; ++i) {
            const glm::dvec3 d = test::random_unit(rng);
            failure_test::check_ray(stone, tracer, *surface, {target - 20.0 * d, d}, kDiamond, 30,
                                    check);
        }
    }
    std::printf("%zu vertices, %zu edges: %d rays traced, %d exits checked by Snell\n",
                stone.vertices.size(), edges.size(), check.traced, check.snell);
    failure_test::expect_clean(check, "round brilliant edges and vertices", 1000);
}

TEST(FailureOpticsEdges, ReferenceImageInWhiteSurroundHasNoLostPixels) {
    const Stone stone = failure_test::round_brilliant(kDiamond);
    ASSERT_FALSE(stone.facets.empty());
    RenderSettings settings;
    settings.width = settings.height = 48;
    settings.samples_per_pixel = 1;
    settings.camera.elevation_deg = 65.0;
    settings.camera.azimuth_deg = 20.0;
    settings.background_is_environment = false;
    settings.trace.max_depth = 200;
    settings.trace.min_weight = 1e-12;
    const Environment white = Environment::uniform(glm::dvec3(1.0));
    auto image = render_reference(stone, white, settings);
    ASSERT_TRUE(image.ok()) << image.error();
    const Image& img = image.value();
    int covered = 0, below_99 = 0;
    double darkest = 1.0;
    for (const glm::vec4& p : img.pixels) {
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        ASSERT_TRUE(p.w == 0.0f || p.w == 1.0f);  // one sample: hit or miss
        if (p.w == 0.0f) {
            EXPECT_EQ(p.x, 0.0f);  // the black background
            continue;
        }
        ++covered;
        // Grey: the white surround is the same in every channel.
        EXPECT_EQ(p.x, p.y);
        EXPECT_EQ(p.y, p.z);
        // Energy: never more than came in; a lost ray would show as far less.
        EXPECT_LE(p.x, 1.0f + 1e-6f);
        darkest = std::min(darkest, double(p.x));
        below_99 += p.x < 0.99f ? 1 : 0;
    }
    std::printf(
        "%d stone pixels; darkest %.4f; %d below 0.99 (light still trapped at depth "
        "200)\n",
        covered, darkest, below_99);
    EXPECT_GT(covered, 48 * 48 / 3);
    // A lost branch would take a sizeable share of the entry transmittance (≥ 0.83 for
    // diamond) with it; the light still trapped at depth 200 is far less (failure_optics_tir_
    // depth: the mean loss of diamond falls under 1 % by depth 23).
    EXPECT_GT(darkest, 0.9);
    EXPECT_LT(below_99, covered / 20);
}

}  // namespace
}  // namespace gem
