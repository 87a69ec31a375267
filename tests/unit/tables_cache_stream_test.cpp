// The view cache as a frame sees it: acquire() answers at once even while the disk is slow,
// with the nearest view already resident, and prefetch decodes the views ahead of a turning
// camera, the coarse level first. Also the cache over a real (small) database.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <set>

#include "gemdb/reader.hpp"
#include "gemdb/view_cache.hpp"
#include "gemdb/view_cache_motion.hpp"
#include "tables_cache_fake.hpp"
#include "tables_test_support.hpp"

namespace gem {
namespace {

using cache_test::FakeSource;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// A direction by azimuth (about +y from +z toward +x) and elevation, written out directly.
glm::dvec3 from_angles(double azimuth, double elevation) {
    return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
            std::cos(elevation) * std::cos(azimuth)};
}

// Every level-0 decode in `order` (view, level) comes before every level-1 decode.
bool coarse_first(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& order) {
    std::size_t last_coarse = 0;
    std::size_t first_fine = order.size();
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (order[i].second == 0) last_coarse = i;
        if (order[i].second == 1) first_fine = std::min(first_fine, i);
    }
    return last_coarse < first_fine;
}

TEST(TablesCacheStream, ColdAcquireReturnsNothingAtOnce) {
    auto source = std::make_shared<FakeSource>(0.3, 2, 100);
    source->shut_gate();
    ViewCache cache(source);
    const AcquiredView got = cache.acquire(from_angles(0.2, 0.4), 1);
    // It came back while the disk had not answered: no decode had finished.
    EXPECT_EQ(source->finished(), 0);
    source->open_gate();
    EXPECT_EQ(got.view, nullptr);
    EXPECT_FALSE(got.exact);
    EXPECT_EQ(cache.stats().misses, 1u);
}

TEST(TablesCacheStream, AcquireNeverWaitsForASlowDecode) {
    auto source = std::make_shared<FakeSource>(0.3, 1, 100);
    ViewCache cache(source);
    const ViewGrid& grid = source->grid();
    const std::uint32_t a = grid.nearest(from_angles(0.0, 0.5)).view;
    (void)cache.acquire(grid.direction(a), 0);
    ASSERT_TRUE(cache.wait_idle(5s));

    // Turn 0.6 rad in azimuth (0.53 rad of arc), onto another view; while its decode waits
    // on the disk, every frame gets view a, and gets it without waiting for that decode.
    const glm::dvec3 asked = from_angles(0.6, 0.5);
    const std::uint32_t b = grid.nearest(asked).view;
    ASSERT_NE(a, b);
    source->shut_gate();
    const int finished_before = source->finished();
    for (int frame = 0; frame < 5; ++frame) {
        const AcquiredView got = cache.acquire(asked, 0);
        EXPECT_EQ(source->finished(), finished_before) << frame;
        ASSERT_NE(got.view, nullptr);
        EXPECT_EQ(got.match.view, a);
        EXPECT_FALSE(got.exact);
        // The group is the identity alone, so the offset is the plain angle between them.
        EXPECT_NEAR(got.match.angle, std::acos(glm::dot(asked, grid.direction(a))), 1e-9);
    }
    source->open_gate();
    ASSERT_TRUE(cache.wait_idle(5s));
    const AcquiredView got = cache.acquire(asked, 0);
    EXPECT_TRUE(got.exact);
    EXPECT_EQ(got.match.view, b);
    EXPECT_EQ(got.view->weight.front(), static_cast<float>(b));
    EXPECT_EQ(cache.stats().decodes, 2u);
}

TEST(TablesCacheStream, WantedLevelIsPreferredThenTheCoarserOne) {
    auto source = std::make_shared<FakeSource>(0.3, 3, 100);
    ViewCache cache(source);
    const glm::dvec3 asked = source->grid().direction(4);
    (void)cache.acquire(asked, 1);
    ASSERT_TRUE(cache.wait_idle(5s));
    // Decoded: the coarse level first, then the wanted one; never the finer one.
    const auto order = source->decoded();
    ASSERT_EQ(order.size(), 2u);
    EXPECT_EQ(order[0], std::make_pair(4u, 0u));
    EXPECT_EQ(order[1], std::make_pair(4u, 1u));
    const AcquiredView exact = cache.acquire(asked, 1);
    EXPECT_TRUE(exact.exact);
    EXPECT_EQ(exact.level, 1u);
    EXPECT_EQ(exact.view->side, 2u);  // the fake's side is level + 1
    // Asking for level 2 shows level 1 meanwhile.
    const AcquiredView finer = cache.acquire(asked, 2);
    EXPECT_FALSE(finer.exact);
    EXPECT_EQ(finer.level, 1u);
    EXPECT_EQ(finer.match.view, 4u);
}

TEST(TablesCacheStream, PrefetchDecodesTheViewsAheadCoarseFirst) {
    auto source = std::make_shared<FakeSource>(0.3, 2, 100);
    ViewCacheOptions options;
    options.prefetch_horizon_s = 0.5;
    ViewCache cache(source, options);
    const ViewGrid& grid = source->grid();
    // Turning about +y at 1.2 rad/s moves the azimuth up by 0.6 rad in the horizon.
    const double elevation = 0.3;
    const glm::dvec3 here = from_angles(0.0, elevation);
    const std::size_t queued = cache.prefetch(here, {0.0, 1.2, 0.0}, 1);
    EXPECT_GT(queued, 0u);
    ASSERT_TRUE(cache.wait_idle(5s));
    const auto order = source->decoded();
    ASSERT_EQ(order.size(), queued);

    // The views nearest to points half-way and at the end of the predicted arc are in, at
    // both levels; so is nothing behind the camera.
    for (double azimuth : {0.3, 0.6}) {
        const std::uint32_t v = grid.nearest(from_angles(azimuth, elevation)).view;
        EXPECT_TRUE(cache.resident(v, 0)) << azimuth;
        EXPECT_TRUE(cache.resident(v, 1)) << azimuth;
    }
    for (double azimuth : {-0.3, -0.6}) {
        const std::uint32_t v = grid.nearest(from_angles(azimuth, elevation)).view;
        EXPECT_FALSE(cache.resident(v, 0)) << azimuth;
    }
    // Every prefetched view lies ahead, within the arc plus half a grid cell or so.
    for (const auto& [view, level] : order) {
        const glm::dvec3 d = grid.direction(view);
        const double azimuth = std::atan2(d.x, d.z);
        EXPECT_GT(azimuth, 0.0) << view;
        EXPECT_LT(azimuth, 0.6 + 0.3) << view;
    }
    EXPECT_TRUE(coarse_first(order));
    // Nearest in time first: the first decode is the first view met along the arc.
    std::uint32_t first_met = grid.nearest(here).view;
    for (int i = 1; i <= 600 && first_met == grid.nearest(here).view; ++i) {
        first_met = grid.nearest(from_angles(0.6 * i / 600.0, elevation)).view;
    }
    EXPECT_EQ(order.front().first, first_met);
}

// A piece's stones of one kind face the camera from different directions: one prefetch for
// all of them decodes what lies ahead of each, every stone's coarse level first.
TEST(TablesCacheStream, PrefetchForSeveralStonesDecodesWhatLiesAheadOfEach) {
    auto source = std::make_shared<FakeSource>(0.3, 2, 100);
    ViewCache cache(source);
    const ViewGrid& grid = source->grid();
    // Two stones turned half a turn apart about y, the view turning about +y at 1.2 rad/s.
    const double elevation = 0.3;
    const ViewHeading headings[2] = {{from_angles(0.0, elevation), {0.0, 1.2, 0.0}},
                                     {from_angles(3.0, elevation), {0.0, 1.2, 0.0}}};
    const std::size_t queued = cache.prefetch(headings, 1);
    ASSERT_TRUE(cache.wait_idle(5s));
    const auto order = source->decoded();
    ASSERT_EQ(order.size(), queued);
    for (double start : {0.0, 3.0}) {
        const std::uint32_t ahead = grid.nearest(from_angles(start + 0.6, elevation)).view;
        const std::uint32_t behind = grid.nearest(from_angles(start - 0.6, elevation)).view;
        EXPECT_TRUE(cache.resident(ahead, 0)) << start;
        EXPECT_TRUE(cache.resident(ahead, 1)) << start;
        EXPECT_FALSE(cache.resident(behind, 0)) << start;
    }
    EXPECT_TRUE(coarse_first(order));
}

TEST(TablesCacheStream, DemandOutranksPrefetch) {
    auto source = std::make_shared<FakeSource>(0.3, 1, 100);
    source->delay = 30ms;
    ViewCache cache(source);
    const ViewGrid& grid = source->grid();
    (void)cache.prefetch(from_angles(0.0, 0.0), {0.0, 3.0, 0.0}, 0);
    const glm::dvec3 asked = from_angles(3.0, -0.8);  // far from the prefetched arc
    (void)cache.acquire(asked, 0);
    ASSERT_TRUE(cache.wait_idle(5s));
    const auto order = source->decoded();
    ASSERT_GE(order.size(), 3u);
    // At most the prefetch already in flight runs before the frame's request.
    const std::uint32_t wanted = grid.nearest(asked).view;
    EXPECT_TRUE(order[0].first == wanted || order[1].first == wanted);
}

TEST(TablesCacheStream, ServesARealDatabase) {
    const auto path = tables_test::artifact_dir("cache") / "small.gemdb";
    const auto small = tables_test::small_database(false);
    ASSERT_TRUE(tables_test::write_small(path, small).ok());
    auto db = Database::open(path);
    ASSERT_TRUE(db.ok()) << db.error();
    auto shared = std::make_shared<const Database>(std::move(db).value());
    ViewCache cache(std::make_shared<DatabaseViewSource>(shared));
    const glm::dvec3 asked = from_angles(0.4, 0.2);
    const ViewMatch match = shared->grid().nearest(asked);
    (void)cache.acquire(asked, 1);
    ASSERT_TRUE(cache.wait_idle(5s));
    const AcquiredView got = cache.acquire(asked, 1);
    ASSERT_TRUE(got.exact);
    EXPECT_EQ(got.match.view, match.view);
    EXPECT_EQ(got.match.symmetry, match.symmetry);
    // Same arrays as a direct decode; the counts themselves come from the stand-in tracer.
    const DecodedView direct = shared->decode(match.view, 1).value();
    EXPECT_EQ(got.view->side, 16u);
    EXPECT_EQ(got.view->ray_count, direct.ray_count);
    EXPECT_EQ(got.view->weight, direct.weight);
    std::size_t expected_hits = 0;
    const auto lists = tables_test::random_lists(tables_test::chunk_seed(match.view, 1), 16);
    for (const RayList& list : lists) expected_hits += list.hit;
    std::size_t hits = 0;
    for (std::uint16_t c : got.view->ray_count) hits += c > 0;
    EXPECT_EQ(hits, expected_hits);
}

// When none of the views near the asked direction is in, the stand-in is the resident view at
// the smallest angle over all of them (each counted once, whichever levels are in), as
// nearest_image() measures it.
TEST(TablesCacheStream, FallbackIsTheNearestResidentView) {
    auto source = std::make_shared<FakeSource>(0.3, 2, 100);
    ViewCache cache(source);
    const ViewGrid& grid = source->grid();
    // Some views with both levels in, some with only the coarse one.
    const std::uint32_t a = grid.nearest(from_angles(0.0, 1.0)).view;
    const std::uint32_t b = grid.nearest(from_angles(0.8, 0.9)).view;
    const std::uint32_t c = grid.nearest(from_angles(-0.7, 0.6)).view;
    const std::uint32_t d = grid.nearest(from_angles(2.5, 0.7)).view;
    (void)cache.acquire(grid.direction(a), 1);
    (void)cache.acquire(grid.direction(b), 0);
    (void)cache.acquire(grid.direction(c), 1);
    (void)cache.acquire(grid.direction(d), 0);
    ASSERT_TRUE(cache.wait_idle(5s));
    source->shut_gate();
    for (const glm::dvec3& asked : {from_angles(0.3, -0.3), from_angles(-1.2, -0.1),
                                    from_angles(2.2, -0.2), from_angles(0.9, 0.1)}) {
        std::array<ViewMatch, 8> near{};
        const std::size_t found = grid.nearest_k(asked, near);
        bool near_resident = false;
        for (std::size_t i = 0; i < found; ++i) {
            for (std::uint32_t l = 0; l < 2; ++l) near_resident |= cache.resident(near[i].view, l);
        }
        ASSERT_FALSE(near_resident) << "the test wants a direction away from the resident views";
        std::optional<ViewMatch> expected;
        for (std::uint32_t v = 0; v < grid.size(); ++v) {
            if (!cache.resident(v, 0) && !cache.resident(v, 1)) continue;
            const ViewMatch m = nearest_image(grid, v, glm::normalize(asked));
            if (!expected || m.angle < expected->angle) expected = m;
        }
        ASSERT_TRUE(expected.has_value());
        const AcquiredView got = cache.acquire(asked, 1);
        ASSERT_NE(got.view, nullptr);
        EXPECT_FALSE(got.exact);
        EXPECT_EQ(got.match.view, expected->view);
        EXPECT_EQ(got.match.symmetry, expected->symmetry);
        EXPECT_NEAR(got.match.angle, expected->angle, 1e-12);
        EXPECT_EQ(got.level, cache.resident(expected->view, 1) ? 1u : 0u);
        EXPECT_EQ(got.view->weight.front(), static_cast<float>(expected->view));
    }
    source->open_gate();
}

}  // namespace
}  // namespace gem
