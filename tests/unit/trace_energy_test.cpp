// Energy and Snell's law over many random rays. With no absorption every unit of light that
// meets a stone is reflected, leaves, or is counted as truncated, so the three add up to 1.
// Snell's law is checked from the geometry of the ray-list alone: the internal direction
// before an exit is the chord between consecutive surface points, and the law is tested in
// its vector form n₁ (d₁ × N) = n₂ (d₂ × N) (Born & Wolf §1.5.1), sharing no code with the
// tracer's refract().

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "trace/tracer.hpp"
#include "trace_cut_stones.hpp"
#include "trace_test_stones.hpp"

namespace gem {
namespace {

Ray random_ray_at(const Stone& stone, std::mt19937_64& rng) {
    const double size = test::bounding_diagonal(stone);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    const glm::dvec3 target{u(rng) * size, u(rng) * size * 0.6, u(rng) * size};
    const glm::dvec3 d = test::random_unit(rng);
    return {target - 2.0 * size * d, d};
}

double total(const RayList& list) {
    double sum = list.reflected.weight + list.truncated_weight;
    for (const TracedRay& e : list.exits) sum += e.weight;
    return sum;
}

struct EnergyStats {
    int hits = 0;
    int deep_complete = 0;  // hits whose truncated energy is below 1e-6
};

EnergyStats check_energy(const Stone& stone, double ior, const TraceSettings& settings, int rays,
                         std::uint64_t seed) {
    const Tracer tracer(stone);
    std::mt19937_64 rng(seed);
    RayList list;
    EnergyStats stats;
    for (int i = 0; i < rays; ++i) {
        tracer.trace(random_ray_at(stone, rng), ior, settings, list);
        if (!list.hit) continue;
        ++stats.hits;
        EXPECT_NEAR(total(list), 1.0, 1e-9) << stone.name << " ray " << i;
        if (list.truncated_weight < 1e-6) ++stats.deep_complete;
    }
    return stats;
}

std::vector<Stone> test_stones() {
    std::vector<Stone> stones = test::all_cuts();
    stones.push_back(test::box_stone(1.0, 1.0, 1.0));
    Stone bvh_cube = test::box_stone(1.0, 1.0, 1.0);
    bvh_cube.name = "box (bvh)";
    bvh_cube.convex = false;
    stones.push_back(bvh_cube);
    stones.push_back(test::star_prism_stone(5, 3.0, 1.2, 0.8));
    return stones;
}

TEST(TraceEnergy, ReflectedPlusExitsPlusTruncatedIsOne) {
    for (const Stone& stone : test_stones()) {
        for (WeightModel model : {WeightModel::fresnel, WeightModel::thesis_factors}) {
            TraceSettings settings;
            settings.weights = model;
            const EnergyStats s = check_energy(stone, test::kDiamondIndex, settings, 3000, 11);
            EXPECT_GT(s.hits, 500) << stone.name;
        }
    }
}

TEST(TraceEnergy, DeepTreeLeavesLittleTruncated) {
    TraceSettings settings;
    settings.max_depth = 200;
    settings.min_weight = 1e-12;
    for (const Stone& stone : test_stones()) {
        // Glass rather than diamond: fewer total internal reflections, as in the brief's cube.
        const double ior = stone.name.starts_with("box") ? 1.5 : test::kDiamondIndex;
        const EnergyStats s = check_energy(stone, ior, settings, 2000, 12);
        const double share = double(s.deep_complete) / std::max(1, s.hits);
        std::printf("%-16s n=%.3f  truncated < 1e-6 for %.1f %% of %d hits\n", stone.name.c_str(),
                    ior, 100.0 * share, s.hits);
        EXPECT_GT(share, 0.5) << stone.name;
    }
}

// Vector Snell: n_in (d_in × N) = n_out (d_out × N), with d_out leaving the facet.
void expect_snell(const glm::dvec3& d_in, const glm::dvec3& d_out, const glm::dvec3& normal,
                  double n_in, double n_out, const std::string& where) {
    const glm::dvec3 lhs = n_in * glm::cross(d_in, normal);
    const glm::dvec3 rhs = n_out * glm::cross(d_out, normal);
    EXPECT_NEAR(glm::length(lhs - rhs), 0.0, 1e-7) << where;
    EXPECT_GT(glm::dot(d_out, normal) * glm::dot(d_in, normal), 0.0) << where;
}

TEST(TraceEnergy, EveryExitObeysSnell) {
    TraceSettings settings;
    settings.max_depth = 20;
    settings.min_weight = 0.0;
    for (const Stone& stone : test_stones()) {
        if (!stone.convex) continue;  // a single chain of surface points per ray
        const Tracer tracer(stone);
        const double ior = test::kDiamondIndex;
        std::mt19937_64 rng(13);
        RayList list;
        int checked = 0;
        for (int i = 0; i < 2000; ++i) {
            const Ray ray = random_ray_at(stone, rng);
            tracer.trace(ray, ior, settings, list);
            if (!list.hit) continue;
            const glm::dvec3 entry = list.reflected.origin;
            // Surface points by bounce count; an exit at bounce b is preceded by the point of
            // bounce b − 1 (the entry for b = 0), known when that bounce also let light out.
            std::vector<const TracedRay*> by_bounce(settings.max_depth + 1, nullptr);
            for (const TracedRay& e : list.exits) by_bounce[e.bounces] = &e;
            for (const TracedRay& e : list.exits) {
                const glm::dvec3* previous = nullptr;
                if (e.bounces == 0) {
                    previous = &entry;
                } else if (by_bounce[e.bounces - 1]) {
                    previous = &by_bounce[e.bounces - 1]->origin;
                }
                if (!previous || glm::length(e.origin - *previous) < 1e-6) continue;
                const glm::dvec3 d_in = glm::normalize(e.origin - *previous);
                const glm::dvec3& n = stone.facets[e.facet].plane.n;
                expect_snell(d_in, e.direction, n, ior, 1.0, stone.name);
                EXPECT_NEAR(stone.facets[e.facet].plane.signed_distance(e.origin), 0.0, 1e-9);
                ++checked;
                if (e.bounces == 0) {
                    // The entry refraction: the same law from air into the stone.
                    const glm::dvec3& n_entry = stone.facets[list.reflected.facet].plane.n;
                    expect_snell(ray.direction, d_in, -n_entry, 1.0, ior, stone.name);
                }
            }
        }
        EXPECT_GT(checked, 300) << stone.name;  // diamond reflects most chains totally
    }
}

}  // namespace
}  // namespace gem
