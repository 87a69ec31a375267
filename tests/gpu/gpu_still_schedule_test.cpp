// How a still view is refined (gpu/still_schedule.hpp): its frames' depths written out by hand
// from the rule, its time, its frame count, and the cost bound that keeps a touch answered.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "gpu/still_schedule.hpp"

namespace gem::gpu {
namespace {

// A still view's frames, one a second apart, each reported to cost `ms_per_depth` per unit of
// its depth: {depth, bands} of each until it settles or has `limit` frames.
std::vector<std::pair<int, int>> frames_of(StillSchedule& s, double ms_per_depth = 1.0,
                                           int limit = 2000) {
    std::vector<std::pair<int, int>> out;
    s.begin_frame(false, 0.0);  // moving
    for (int f = 0; f < limit; ++f) {
        s.begin_frame(true, f);
        if (s.settled()) break;
        out.emplace_back(s.depth(), s.bands());
        s.frame_drawn(ms_per_depth * s.depth());
    }
    return out;
}

// Their depths alone.
std::vector<int> depths(StillSchedule& s, double ms_per_depth = 1.0, int limit = 2000) {
    std::vector<int> out;
    for (const auto& [depth, bands] : frames_of(s, ms_per_depth, limit)) out.push_back(depth);
    return out;
}

TEST(StillSchedule, TheDepthDoublesEachTimeTheFramesDoubleUpToItsMaximum) {
    StillSchedule s({.frames = 80, .depth = 16, .depth_max = 64});
    const std::vector<int> d = depths(s);
    ASSERT_EQ(d.size(), 80u);  // frames 0..79, then settled
    for (int i = 0; i < 16; ++i) EXPECT_EQ(d[i], 16) << i;
    for (int i = 16; i < 32; ++i) EXPECT_EQ(d[i], 32) << i;
    for (int i = 32; i < 80; ++i) EXPECT_EQ(d[i], 64) << i;  // 128 wanted at 64, held at 64
    EXPECT_TRUE(s.settled());
    EXPECT_EQ(s.depth(), 0);
}

TEST(StillSchedule, WithoutAMaximumOrAFirstDepthItNeverDeepens) {
    StillSchedule fixed({.frames = 40, .depth = 16, .depth_max = 0});
    for (int d : depths(fixed)) EXPECT_EQ(d, 16);
    StillSchedule moving_depth({.frames = 40, .depth = 0, .depth_max = 64});
    for (int d : depths(moving_depth)) EXPECT_EQ(d, 0);
    // A maximum that is not a doubling of the first depth is reached, not passed.
    StillSchedule odd({.frames = 40, .depth = 16, .depth_max = 24});
    const std::vector<int> d = depths(odd);
    EXPECT_EQ(d[15], 16);
    EXPECT_EQ(d[16], 24);
    EXPECT_EQ(d[39], 24);
}

TEST(StillSchedule, ItSettlesWhenItsTimeIsUpAndATouchRestartsIt) {
    // One frame a second (depths()), 10 s: the frames begun at 0..9 s; the one at 10 s settles.
    StillSchedule s({.frames = 1024, .depth = 16, .depth_max = 64, .seconds = 10.0});
    EXPECT_EQ(depths(s).size(), 10u);
    EXPECT_TRUE(s.settled());
    s.begin_frame(true, 100.0);  // still: stays settled
    EXPECT_TRUE(s.settled());
    s.begin_frame(false, 100.0);  // a touch moved it
    EXPECT_FALSE(s.settled());
    EXPECT_EQ(s.index(), -1);
    s.begin_frame(true, 100.5);
    EXPECT_EQ(s.index(), 0);
    EXPECT_EQ(s.depth(), 16);
    s.begin_frame(true, 110.4);  // 9.9 s after the view's first frame
    EXPECT_FALSE(s.settled());
    s.begin_frame(true, 110.5);
    EXPECT_TRUE(s.settled());
}

TEST(StillSchedule, AFrameLongerThanTheBoundIsDrawnInBandsAndTooManyBandsTraceShallower) {
    const StillScheduleOptions bound{.frames = 64, .depth = 16, .depth_max = 64, .frame_ms = 100.0};
    // 2 ms per unit of depth: 16 → 32 ms and 32 → 64 ms whole; 64 → 128 ms, in 2 bands.
    StillSchedule quick(bound);
    auto d = frames_of(quick, 2.0, 64);
    EXPECT_EQ(d[15], std::make_pair(16, 1));
    EXPECT_EQ(d[16], std::make_pair(32, 1));
    EXPECT_EQ(d[40], std::make_pair(64, 2));
    // 8 ms per unit: even 16 (128 ms) takes 2 bands, once a frame has been measured (the
    // view's first is multisampled and not counted, the second no deeper than the first);
    // 32 → 256 ms in 3; 64 → 512 ms in 6.
    StillSchedule slow(bound);
    d = frames_of(slow, 8.0, 64);
    EXPECT_EQ(d[0], std::make_pair(16, 1));
    EXPECT_EQ(d[1], std::make_pair(16, 1));
    EXPECT_EQ(d[2], std::make_pair(16, 2));
    EXPECT_EQ(d[16], std::make_pair(32, 3));
    EXPECT_EQ(d[40], std::make_pair(64, 6));
    // 20 ms per unit: 64 takes 13 bands of 100 ms, within kMostBands (16).
    StillSchedule slower(bound);
    d = frames_of(slower, 20.0, 64);
    EXPECT_EQ(d[40], std::make_pair(64, 13));
    // 40 ms per unit: 64 would take 26, more than kMostBands: 32 in 13.
    StillSchedule slower_still(bound);
    d = frames_of(slower_still, 40.0, 64);
    EXPECT_EQ(d[40], std::make_pair(32, 13));
    // 160 ms per unit: 16 itself takes 26; never shallower than the first depth, in at most 16.
    StillSchedule slowest(bound);
    d = frames_of(slowest, 160.0, 64);
    EXPECT_EQ(d[40], std::make_pair(16, StillSchedule::kMostBands));
}

TEST(StillSchedule, OneFrameIsNoStillViewAndTheFrameCountEndsIt) {
    StillSchedule none({.frames = 1, .depth = 16});
    none.begin_frame(true, 0.0);
    EXPECT_EQ(none.index(), -1);
    EXPECT_FALSE(none.settled());
    StillSchedule four({.frames = 4, .depth = 16});
    EXPECT_EQ(depths(four).size(), 4u);
    EXPECT_EQ(four.index(), 3);  // the last frame drawn stays the mean's last
}

}  // namespace
}  // namespace gem::gpu
