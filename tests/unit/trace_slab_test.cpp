// A glass slab (a flat box) at normal and oblique incidence, against the textbook series: at
// normal incidence R = ((n − 1)/(n + 1))² per interface (Born & Wolf §1.5.2), the k-th exit ray
// has weight (1 − R)² R^k, travels (k + 1) thicknesses inside and alternates down / up.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "trace/tracer.hpp"
#include "trace_test_stones.hpp"

namespace gem {
namespace {

constexpr double kIndex = 1.5;
constexpr double kThickness = 1.0;  // box half-height 0.5

Stone slab(bool convex) {
    Stone s = test::box_stone(2.0, kThickness / 2, 2.0);
    s.convex = convex;  // false sends the same box through the triangle BVH
    return s;
}

void sort_by_bounces(RayList& list) {
    std::sort(list.exits.begin(), list.exits.end(),
              [](const TracedRay& a, const TracedRay& b) { return a.bounces < b.bounces; });
}

class TraceSlab : public ::testing::TestWithParam<bool> {};

TEST_P(TraceSlab, NormalIncidenceFollowsTheAnalyticSeries) {
    const Stone stone = slab(GetParam());
    const Tracer tracer(stone);
    TraceSettings settings;
    settings.max_depth = 30;
    settings.min_weight = 1e-300;
    RayList list;
    tracer.trace({{0.3, 5.0, -0.2}, {0.0, -1.0, 0.0}}, kIndex, settings, list);
    ASSERT_TRUE(list.hit);

    const double r = std::pow((kIndex - 1) / (kIndex + 1), 2.0);  // 0.04
    EXPECT_NEAR(list.reflected.weight, r, 1e-15);
    EXPECT_EQ(list.reflected.direction, glm::dvec3(0, 1, 0));
    EXPECT_NEAR(list.reflected.origin.y, kThickness / 2, 1e-15);
    EXPECT_EQ(list.reflected.facet, 2u);  // +y

    sort_by_bounces(list);
    ASSERT_EQ(list.exits.size(), 30u);  // every internal segment ends in one exit
    for (std::size_t k = 0; k < list.exits.size(); ++k) {
        const TracedRay& e = list.exits[k];
        const bool down = k % 2 == 0;
        EXPECT_EQ(e.bounces, k);
        EXPECT_NEAR(e.weight, (1 - r) * (1 - r) * std::pow(r, double(k)), 1e-15) << k;
        EXPECT_NEAR(e.path_mm, (k + 1) * kThickness, 1e-12) << k;
        EXPECT_EQ(e.direction, glm::dvec3(0, down ? -1 : 1, 0)) << k;
        EXPECT_NEAR(e.origin.x, 0.3, 1e-15);
        EXPECT_NEAR(e.origin.z, -0.2, 1e-15);
        EXPECT_NEAR(e.origin.y, down ? -kThickness / 2 : kThickness / 2, 1e-15);
        EXPECT_EQ(e.facet, down ? 3u : 2u);
    }
    // The branch cut after 30 segments still carries (1 − R) R^30.
    EXPECT_NEAR(list.truncated_weight, (1 - r) * std::pow(r, 30.0), 1e-18);
}

TEST_P(TraceSlab, ThesisFactorsReplaceFresnel) {
    const Stone stone = slab(GetParam());
    const Tracer tracer(stone);
    TraceSettings settings;
    settings.weights = WeightModel::thesis_factors;
    settings.r_factor = 0.3;
    settings.t_factor = 0.7;
    settings.max_depth = 5;  // the thesis traced 5 segments
    settings.min_weight = 0.0;
    RayList list;
    tracer.trace({{0.0, 3.0, 0.0}, {0.0, -1.0, 0.0}}, kIndex, settings, list);
    ASSERT_TRUE(list.hit);
    EXPECT_DOUBLE_EQ(list.reflected.weight, 0.3);
    sort_by_bounces(list);
    ASSERT_EQ(list.exits.size(), 5u);
    for (std::size_t k = 0; k < 5; ++k) {
        EXPECT_NEAR(list.exits[k].weight, 0.7 * 0.7 * std::pow(0.3, double(k)), 1e-15);
    }
    EXPECT_NEAR(list.truncated_weight, 0.7 * std::pow(0.3, 5.0), 1e-15);
}

TEST_P(TraceSlab, ObliqueIncidenceKeepsDirectionsAndShiftsBySnell) {
    const Stone stone = slab(GetParam());
    const Tracer tracer(stone);
    TraceSettings settings;
    settings.max_depth = 6;
    settings.min_weight = 0.0;
    const double theta_i = 0.6;  // radians from the normal, in the xy plane
    const glm::dvec3 d{std::sin(theta_i), -std::cos(theta_i), 0.0};
    const glm::dvec3 entry{-1.0, kThickness / 2, 0.1};
    RayList list;
    tracer.trace({entry - 4.0 * d, d}, kIndex, settings, list);
    ASSERT_TRUE(list.hit);
    EXPECT_NEAR(glm::length(list.reflected.origin - entry), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(list.reflected.direction - glm::dvec3(d.x, -d.y, 0)), 0, 1e-15);

    // Inside, sin θt = sin θi / n; each segment moves tan θt · thickness along x.
    const double theta_t = std::asin(std::sin(theta_i) / kIndex);
    const double step = kThickness * std::tan(theta_t);
    sort_by_bounces(list);
    ASSERT_EQ(list.exits.size(), 6u);
    for (std::size_t k = 0; k < list.exits.size(); ++k) {
        const TracedRay& e = list.exits[k];
        const bool down = k % 2 == 0;
        // Parallel faces: every exit leaves parallel to the incoming ray or its mirror image.
        const glm::dvec3 expected = down ? d : glm::dvec3(d.x, -d.y, 0);
        EXPECT_NEAR(glm::length(e.direction - expected), 0.0, 1e-14) << k;
        EXPECT_NEAR(e.origin.x, entry.x + (k + 1) * step, 1e-12) << k;
        EXPECT_NEAR(e.path_mm, (k + 1) * kThickness / std::cos(theta_t), 1e-12) << k;
    }
}

TEST_P(TraceSlab, MissGivesAnEmptyList) {
    const Stone stone = slab(GetParam());
    const Tracer tracer(stone);
    RayList list;
    list.exits.resize(3);  // stale content must be cleared
    list.hit = true;
    tracer.trace({{5.0, 5.0, 0.0}, {0.0, -1.0, 0.0}}, kIndex, TraceSettings{}, list);
    EXPECT_FALSE(list.hit);
    EXPECT_TRUE(list.exits.empty());
    EXPECT_EQ(list.truncated_weight, 0.0);
    // Pointing away from the stone misses too.
    tracer.trace({{0.0, 5.0, 0.0}, {0.0, 1.0, 0.0}}, kIndex, TraceSettings{}, list);
    EXPECT_FALSE(list.hit);
}

// Two slabs one above the other, as one (non-convex) stone: light that leaves the upper slab
// downward meets the lower one and must be followed into it.
TEST(TraceSlabPair, LightLeavingOneSlabReentersTheOther) {
    Stone pair = test::box_stone(2.0, 0.5, 2.0);
    const Stone lower = test::box_stone(2.0, 0.25, 2.0);
    const auto offset = static_cast<std::uint32_t>(pair.vertices.size());
    const auto facet_offset = static_cast<std::uint32_t>(pair.facets.size());
    const glm::dvec3 shift{0.0, -2.0, 0.0};  // lower slab spans y = -2.25 .. -1.75
    for (const glm::dvec3& v : lower.vertices) pair.vertices.push_back(v + shift);
    for (Facet f : lower.facets) {
        f.plane.d += glm::dot(f.plane.n, shift);
        for (auto& i : f.loop) i += offset;
        pair.facets.push_back(f);
    }
    for (MeshTriangle t : lower.triangles) {
        for (auto& i : t.v) i += offset;
        t.facet += facet_offset;
        pair.triangles.push_back(t);
    }
    pair.convex = false;

    const Tracer tracer(pair);
    TraceSettings settings;
    settings.max_depth = 40;
    settings.min_weight = 1e-14;
    RayList list;
    tracer.trace({{0.1, 5.0, 0.2}, {0.0, -1.0, 0.0}}, kIndex, settings, list);
    ASSERT_TRUE(list.hit);
    const double r = std::pow((kIndex - 1) / (kIndex + 1), 2.0);
    const double t = 1.0 - r;

    // The straight-through ray crosses four interfaces and 1 + 0.5 mm of glass.
    const TracedRay* through = nullptr;
    for (const TracedRay& e : list.exits) {
        // Nothing may leave downward from the upper slab: the lower one is in the way.
        EXPECT_FALSE(e.direction.y < 0.0 && std::abs(e.origin.y + 0.5) < 1e-12);
        // Outside reflections between the slabs do not count as bounces, so the direct ray
        // is the strongest of the downward exits with no internal reflection.
        if (e.bounces == 0 && e.direction.y < 0.0 && (!through || e.weight > through->weight)) {
            through = &e;
        }
    }
    ASSERT_NE(through, nullptr);
    EXPECT_NEAR(through->weight, t * t * t * t, 1e-15);
    EXPECT_NEAR(through->path_mm, 1.5, 1e-12);
    EXPECT_NEAR(through->origin.y, -2.25, 1e-12);
    EXPECT_EQ(through->facet, facet_offset + 3);  // the lower slab's -y facet

    double sum = list.reflected.weight + list.truncated_weight;
    double down = 0.0;
    for (const TracedRay& e : list.exits) {
        sum += e.weight;
        if (e.direction.y < 0.0) down += e.weight;
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    // Incoherent transmission of two slabs: one slab transmits T1 = (1 - R) / (1 + R) of what
    // meets it, and two non-absorbing layers in series transmit 1 / (1/T1 + 1/T1 - 1).
    const double t1 = (1.0 - r) / (1.0 + r);
    EXPECT_NEAR(down, 1.0 / (2.0 / t1 - 1.0), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(ConvexAndBvh, TraceSlab, ::testing::Values(true, false),
                         [](const auto& param_info) {
                             return param_info.param ? "planes" : "bvh";
                         });

}  // namespace
}  // namespace gem
