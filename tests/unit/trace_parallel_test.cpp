// parallel_for covers every index once, and the tracer gives the same ray-lists from many
// threads as from one (it is const and keeps no per-call state).

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "trace/parallel.hpp"
#include "trace/tracer.hpp"
#include "trace_cut_stones.hpp"
#include "trace_test_stones.hpp"

namespace gem {
namespace {

TEST(TraceParallel, EveryIndexExactlyOnce) {
    for (std::size_t chunk : {1u, 7u, 1000u}) {
        std::vector<std::atomic<int>> seen(1237);
        parallel_for(
            seen.size(),
            [&](std::size_t b, std::size_t e) {
                ASSERT_LT(b, e);
                for (std::size_t i = b; i < e; ++i) ++seen[i];
            },
            chunk);
        for (const auto& s : seen) ASSERT_EQ(s.load(), 1);
    }
    parallel_for(0, [](std::size_t, std::size_t) { FAIL() << "called for an empty range"; });
}

void expect_same(const RayList& a, const RayList& b) {
    ASSERT_EQ(a.hit, b.hit);
    ASSERT_EQ(a.exits.size(), b.exits.size());
    EXPECT_EQ(a.reflected.weight, b.reflected.weight);
    EXPECT_EQ(a.truncated_weight, b.truncated_weight);
    for (std::size_t i = 0; i < a.exits.size(); ++i) {
        EXPECT_EQ(a.exits[i].origin, b.exits[i].origin);
        EXPECT_EQ(a.exits[i].direction, b.exits[i].direction);
        EXPECT_EQ(a.exits[i].weight, b.exits[i].weight);
    }
}

TEST(TraceParallel, ThreadsGiveTheSameRayListsAsOne) {
    std::vector<Stone> stones = test::all_cuts();
    stones.push_back(test::star_prism_stone(5, 3.0, 1.2, 0.8));
    constexpr int kSide = 48;
    for (const Stone& stone : stones) {
        const Tracer tracer(stone);
        auto ray_at = [](int x, int y) {
            const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
            return Ray{{(x - kSide / 2) * 0.15, 10.0, (y - kSide / 2) * 0.15}, d};
        };
        std::vector<RayList> serial(kSide * kSide), threaded(kSide * kSide);
        for (int i = 0; i < kSide * kSide; ++i) {
            tracer.trace(ray_at(i % kSide, i / kSide), 2.417, TraceSettings{}, serial[i]);
        }
        parallel_for(kSide, [&](std::size_t b, std::size_t e) {
            for (std::size_t y = b; y < e; ++y) {
                for (int x = 0; x < kSide; ++x) {
                    tracer.trace(ray_at(x, int(y)), 2.417, TraceSettings{},
                                 threaded[y * kSide + x]);
                }
            }
        });
        int hits = 0;
        for (int i = 0; i < kSide * kSide; ++i) {
            expect_same(serial[i], threaded[i]);
            hits += serial[i].hit;
        }
        EXPECT_GT(hits, 100) << stone.name;
    }
}

}  // namespace
}  // namespace gem
