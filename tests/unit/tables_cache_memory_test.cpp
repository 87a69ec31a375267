// The view cache's memory bound, eviction, sharing with frames and damaged views, against a
// stand-in source whose view sizes and contents are known by construction.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>

#include "gemdb/view_cache.hpp"
#include "tables_cache_fake.hpp"

namespace gem {
namespace {

using cache_test::FakeSource;
using namespace std::chrono_literals;

constexpr std::size_t kFloats = 250;  // 250 floats × 4 bytes = 1000 bytes per view

TEST(TablesCacheMemory, ViewBytesCountEveryArray) {
    DecodedView v;
    v.ray_offset.assign(10, 0);  // 40 bytes
    v.ray_count.assign(10, 0);   // 20
    v.direction.assign(3, {});   // 36
    v.position.assign(2, {});    // 24
    v.dir_dn.assign(1, {});      // 12
    v.facet.assign(5, 0);        // 10
    v.direction.shrink_to_fit();
    EXPECT_EQ(decoded_view_bytes(v), 40u + 20u + 36u + 24u + 12u + 10u);
}

TEST(TablesCacheMemory, BoundIsNeverExceeded) {
    auto source = std::make_shared<FakeSource>(0.3, 1, kFloats);
    ViewCacheOptions options;
    options.memory_bytes = 4500;  // room for four views of 1000 bytes, not five
    ViewCache cache(source, options);
    const auto& dirs = source->grid().directions();
    ASSERT_GE(dirs.size(), 20u);
    for (std::uint32_t v = 0; v < 20; ++v) {
        (void)cache.acquire(dirs[v], 0);
        ASSERT_TRUE(cache.wait_idle(5s));
        const ViewCacheStats s = cache.stats();
        EXPECT_LE(s.bytes_resident, options.memory_bytes);
        EXPECT_EQ(s.bytes_resident, s.views_resident * 1000u);
        EXPECT_TRUE(cache.resident(v, 0));
    }
    const ViewCacheStats s = cache.stats();
    EXPECT_EQ(s.views_resident, 4u);
    EXPECT_EQ(s.evictions, 16u);
    EXPECT_EQ(s.decodes, 20u);
    // The view asked last was inserted last, so it is one of the four kept.
    EXPECT_TRUE(cache.resident(19, 0));
}

TEST(TablesCacheMemory, LeastRecentlyShownViewGoesFirst) {
    auto source = std::make_shared<FakeSource>(0.3, 1, kFloats);
    ViewCacheOptions options;
    options.memory_bytes = 2000;  // two views
    options.prefetch_max_views = 1;
    ViewCache cache(source, options);
    const auto& dirs = source->grid().directions();
    (void)cache.acquire(dirs[0], 0);
    ASSERT_TRUE(cache.wait_idle(5s));
    (void)cache.acquire(dirs[1], 0);  // view 0 stands in meanwhile, then 1 is the newest
    ASSERT_TRUE(cache.wait_idle(5s));
    EXPECT_TRUE(cache.acquire(dirs[0], 0).exact);  // now view 0 is the most recent
    // A third view comes in through prefetch, which shows nothing, so it touches nothing:
    // the camera at the far side of the sphere from view 0, turning about x.
    ASSERT_EQ(cache.prefetch(-dirs[0], {2.0, 0.0, 0.0}, 0), 1u);
    ASSERT_TRUE(cache.wait_idle(5s));
    const std::uint32_t third = source->decoded().back().first;
    ASSERT_NE(third, 0u);
    ASSERT_NE(third, 1u);
    EXPECT_TRUE(cache.resident(0, 0));
    EXPECT_FALSE(cache.resident(1, 0));
    EXPECT_TRUE(cache.resident(third, 0));
}

TEST(TablesCacheMemory, ViewInUseSurvivesEviction) {
    auto source = std::make_shared<FakeSource>(0.3, 1, kFloats);
    ViewCacheOptions options;
    options.memory_bytes = 1000;  // exactly one view
    ViewCache cache(source, options);
    const auto& dirs = source->grid().directions();
    (void)cache.acquire(dirs[5], 0);
    ASSERT_TRUE(cache.wait_idle(5s));
    const AcquiredView held = cache.acquire(dirs[5], 0);
    ASSERT_TRUE(held.exact);
    ASSERT_NE(held.view, nullptr);
    (void)cache.acquire(dirs[6], 0);
    ASSERT_TRUE(cache.wait_idle(5s));
    EXPECT_FALSE(cache.resident(5, 0));
    EXPECT_TRUE(cache.resident(6, 0));
    EXPECT_EQ(cache.stats().evictions, 1u);
    // The frame's copy is the only owner left and its contents are intact (the fake fills a
    // view with its own index).
    EXPECT_EQ(held.view.use_count(), 1);
    ASSERT_EQ(held.view->weight.size(), kFloats);
    EXPECT_EQ(held.view->weight.front(), 5.0f);
    EXPECT_EQ(held.view->weight.back(), 5.0f);
}

TEST(TablesCacheMemory, ViewLargerThanTheBoundIsReportedNotKept) {
    auto source = std::make_shared<FakeSource>(0.3, 1, kFloats);
    ViewCacheOptions options;
    options.memory_bytes = 999;
    std::atomic<int> reports{0};
    ViewCache cache(source, options,
                    [&](std::uint32_t, std::uint32_t, const std::string&) { ++reports; });
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(cache.acquire(source->grid().direction(3), 0).view, nullptr);
        ASSERT_TRUE(cache.wait_idle(5s));
    }
    EXPECT_EQ(reports.load(), 1);
    EXPECT_TRUE(cache.bad(3, 0));
    EXPECT_EQ(cache.stats().bytes_resident, 0u);
}

TEST(TablesCacheMemory, ViewClaimingMoreThanTheBoundIsRefusedBeforeDecoding) {
    auto source = std::make_shared<FakeSource>(0.3, 1, kFloats);
    source->claimed_bytes = 4ull << 30;  // what a damaged index could promise
    std::string report;
    ViewCache cache(source, {}, [&](std::uint32_t, std::uint32_t, const std::string& message) {
        report = message;
    });
    EXPECT_EQ(cache.acquire(source->grid().direction(2), 0).view, nullptr);
    ASSERT_TRUE(cache.wait_idle(5s));
    EXPECT_TRUE(source->decoded().empty());
    EXPECT_TRUE(cache.bad(2, 0));
    EXPECT_NE(report.find("more than the cache's memory bound"), std::string::npos) << report;
}

TEST(TablesCacheMemory, DamagedViewIsReportedOnceAndNotRetried) {
    auto source = std::make_shared<FakeSource>(0.3, 2, kFloats);
    source->damaged.insert({7, 1});
    std::atomic<int> reports{0};
    std::string message;
    ViewCache cache(source, {},
                    [&](std::uint32_t view, std::uint32_t level, const std::string& what) {
                        ++reports;
                        message = std::to_string(view) + "/" + std::to_string(level) + ": " + what;
                    });
    for (int i = 0; i < 5; ++i) {
        (void)cache.acquire(source->grid().direction(7), 1);
        ASSERT_TRUE(cache.wait_idle(5s));
    }
    EXPECT_EQ(reports.load(), 1);
    EXPECT_EQ(message, "7/1: fake: view damaged");
    EXPECT_TRUE(cache.bad(7, 1));
    EXPECT_EQ(cache.stats().failures, 1u);
    int tries = 0;
    for (const auto& [view, level] : source->decoded()) tries += view == 7 && level == 1;
    EXPECT_EQ(tries, 1);
    // The good coarse level still serves the direction.
    const AcquiredView got = cache.acquire(source->grid().direction(7), 1);
    ASSERT_NE(got.view, nullptr);
    EXPECT_EQ(got.match.view, 7u);
    EXPECT_EQ(got.level, 0u);
    EXPECT_FALSE(got.exact);
}

TEST(TablesCacheMemory, DestructorStopsWithWorkQueued) {
    auto source = std::make_shared<FakeSource>(0.3, 1, kFloats);
    source->delay = 20ms;
    {
        ViewCache cache(source);
        (void)cache.prefetch(source->grid().direction(0), {0.0, 20.0, 0.0}, 0);
        (void)cache.acquire(source->grid().direction(1), 0);
    }
    // At most the decode in flight finishes; the queued ones are dropped.
    EXPECT_LE(source->decoded().size(), 2u);
}

}  // namespace
}  // namespace gem
