// The folded exit search (trace/folded_exit.hpp) against the full search over every facet
// (convex_intersector.cpp) on the rays of trace_exit_rays.hpp: the same exit point on every
// ray, and the same facet except where the point lies on two facets' planes (an edge or a
// corner, where either is the exit). Which stones fold, and how far, follows from their
// shapes' symmetry (geometry/cuts/make_cut.cpp: C8v round, C4v square princess and cushion,
// C2v emerald, oval and marquise; the pear has one mirror only).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>

#include "import/load_model.hpp"
#include "picture/camera.hpp"
#include "trace/folded_exit.hpp"
#include "trace/intersector.hpp"
#include "trace_cut_stones.hpp"
#include "trace_exit_rays.hpp"

namespace gem {
namespace {

struct Tally {
    int rays = 0;
    int disagreements = 0;
    int ties = 0;  // the same point, the other facet of an edge or corner
    FoldCost cost;
};

Tally fold_every_kind_of_ray(const Stone& s, const FoldedExit& fold) {
    const auto full = make_convex_intersector(s);
    // Folding reflects the ray by rounded sines and cosines: its t carries a few ulps more.
    const double close = 1e-12 * bounding_radius(s.vertices);
    Tally tally;
    test::for_every_kind_of_exit_ray(
        s, 3000, 12, [&](const glm::dvec3& o, const glm::dvec3& d, std::uint32_t from) {
            SurfaceHit expected;
            SurfaceHit got;
            const bool found = full->next_exit(o, d, from, expected);
            const bool folded = fold.next_exit(o, d, got, &tally.cost);
            ++tally.rays;
            bool agree = found == folded;
            if (agree && found) {
                const bool same_point = glm::length(expected.point - got.point) <= close;
                const bool on_both =
                    std::abs(s.facets[got.facet].plane.signed_distance(expected.point)) <= close;
                agree = same_point && (expected.facet == got.facet || on_both);
                if (agree && expected.facet != got.facet) ++tally.ties;
            }
            if (!agree && ++tally.disagreements <= 5) {
                ADD_FAILURE() << s.name << ": from facet " << from << " at (" << o.x << ", " << o.y
                              << ", " << o.z << ") along (" << d.x << ", " << d.y << ", " << d.z
                              << "): full search facet " << expected.facet << " t " << expected.t
                              << ", fold facet " << got.facet << " t " << got.t;
            }
        });
    return tally;
}

TEST(FoldedExit, AgreesWithTheFullSearchOnEveryCutWithTwoMirrors) {
    // Mirrors folded across after x = 0 and z = 0, per shape (make_cut's groups).
    const std::map<std::string, int> levels = {
        {"round-brilliant", 2}, {"princess", 1}, {"cushion", 1},
        {"emerald", 0},         {"oval", 0},     {"marquise", 0}};
    int folded_stones = 0;
    for (const Stone& s : test::all_cuts()) {
        const auto fold = FoldedExit::make(s);
        const auto expected = levels.find(s.name);
        if (expected == levels.end()) {
            EXPECT_FALSE(fold.has_value()) << s.name << " has no two mirrors to fold by";
            continue;
        }
        ASSERT_TRUE(fold.has_value()) << s.name;
        EXPECT_EQ(fold->levels(), expected->second) << s.name;
        ++folded_stones;
        const Tally t = fold_every_kind_of_ray(s, *fold);
        EXPECT_EQ(t.disagreements, 0) << s.name << " over " << t.rays << " rays";
        EXPECT_GT(t.rays, 15000) << s.name;
        const double planes = static_cast<double>(t.cost.planes) / t.cost.searches;
        const double rounds = static_cast<double>(t.cost.rounds) / t.cost.searches;
        // A round ends on a new wedge, so no search takes more rounds than there are wedges.
        EXPECT_LE(t.cost.most_rounds, fold->wedges()) << s.name;
        // The first guess (the turned outline) puts most exits in the first round: a check on
        // its quality, deterministic (the rays are seeded), not on any timing.
        EXPECT_LT(rounds, 1.1) << s.name;
        std::printf(
            "%-16s %3zu facets, %2d wedges, %2zu candidates: %d rays, %.2f rounds and %.1f "
            "planes per exit, at most %d rounds, %d ties\n",
            s.name.c_str(), s.facets.size(), fold->wedges(), fold->candidates().size(), t.rays,
            rounds, planes, t.cost.most_rounds, t.ties);
    }
    EXPECT_EQ(folded_stones, 6);
}

TEST(FoldedExit, TheBrilliantsWedgeHoldsOneFacetOfEachTier) {
    // The point of folding: a round tests few planes. The brilliant's wedge of 22.5° between
    // two mirrors holds, counted by hand from its 8-fold layout (brilliant.cpp): the table,
    // one star, one bezel, one upper girdle facet, one pavilion main, one lower girdle facet
    // and two girdle facets. The facets that only touch its mirror lines (the neighbouring
    // star, bezel, upper and lower girdle and girdle facets) and the pavilion mains that only
    // touch the axis at the culet are left out.
    const Stone s = test::all_cuts().front();
    ASSERT_EQ(s.name, "round-brilliant");
    const auto fold = FoldedExit::make(s);
    ASSERT_TRUE(fold.has_value());
    EXPECT_EQ(fold->wedges(), 16);
    std::map<std::string, int> tiers;
    for (std::uint32_t c : fold->candidates()) ++tiers[s.facets[c].name];
    const std::map<std::string, int> expected = {
        {"table", 1},         {"star", 1},         {"bezel", 1}, {"upper girdle", 1},
        {"pavilion main", 1}, {"lower girdle", 1}, {"girdle", 2}};
    EXPECT_EQ(tiers, expected);
}

TEST(FoldedExit, FoldingAndUnfoldingAreInverse) {
    const auto fold = FoldedExit::make(test::all_cuts().front());
    ASSERT_TRUE(fold.has_value());
    std::mt19937_64 rng(3);
    for (int i = 0; i < 1000; ++i) {
        const glm::dvec3 v = test::random_unit(rng);
        const std::uint32_t bits = fold->fold_bits({v.x, v.z});
        const glm::dvec3 folded = fold->fold(v, bits);
        // Into the first wedge, [0°, 22.5°] of azimuth, by an orthogonal map.
        const double azimuth = std::atan2(folded.z, folded.x);
        EXPECT_GE(azimuth, -1e-12);
        EXPECT_LE(azimuth, std::numbers::pi / 8.0 + 1e-12);
        EXPECT_NEAR(folded.y, v.y, 0.0);
        EXPECT_NEAR(glm::length(folded), 1.0, 1e-12);
        const glm::dvec3 back = fold->unfold(folded, bits);
        EXPECT_NEAR(glm::length(back - v), 0.0, 1e-12);
    }
}

TEST(FoldedExit, AGemCadDesignFoldsWhenItsPlanesAreMirrored) {
    auto stone = load_model(std::filesystem::path(GEM_TEST_DATA_DIR) / "gemcad" / "SRB.asc");
    ASSERT_TRUE(stone.ok()) << stone.error();
    const auto fold = FoldedExit::make(stone.value());
    if (!fold) GTEST_SKIP() << "the design's planes are not mirrored by x = 0 and z = 0";
    const Tally t = fold_every_kind_of_ray(stone.value(), *fold);
    EXPECT_EQ(t.disagreements, 0) << "over " << t.rays << " rays";
}

}  // namespace
}  // namespace gem
