// FrameStats: quantiles by nearest rank and the summary's frame rate, checked against hand
// calculations.
#include <gtest/gtest.h>

#include "service/frame_stats.hpp"

namespace gem::kiosk {
namespace {

TEST(FrameStats, QuantileIsTheNearestRank) {
    // Nearest rank: the ceil(p n)-th smallest. For 1..10: p50 -> 5th = 5, p90 -> 9th = 9,
    // p99 -> ceil(9.9) = 10th = 10, p0 -> the smallest.
    std::vector<double> v{7, 3, 10, 1, 9, 2, 8, 4, 6, 5};
    EXPECT_EQ(quantile(v, 0.5), 5.0);
    EXPECT_EQ(quantile(v, 0.9), 9.0);
    EXPECT_EQ(quantile(v, 0.99), 10.0);
    EXPECT_EQ(quantile(v, 0.0), 1.0);
    EXPECT_EQ(quantile({}, 0.5), 0.0);
}

TEST(FrameStats, SummaryCountsFramesOverTheirSpan) {
    FrameStats stats;
    // Four frames starting every 0.5 s, each 100 ms: from 0 to 1.6 s, so 4 / 1.6 = 2.50 frames/s.
    for (int i = 0; i < 4; ++i) {
        stats.add({.start_s = 0.5 * i,
                   .draw_ms = 100.0,
                   .interval_ms = i ? 500.0 : 0.0,
                   .latency_ms = i == 2 ? 42.0 : -1.0});
    }
    const std::string s = stats.summary();
    EXPECT_NE(s.find("4 frames in 1.6 s: 2.50 frames/s"), std::string::npos) << s;
    EXPECT_NE(s.find("input-to-frame ms p50 42.0"), std::string::npos) << s;
    EXPECT_NE(s.find("(1 frames with new input)"), std::string::npos) << s;
}

TEST(FrameStats, FramesShownAgainCountButDoNotTime) {
    FrameStats stats;
    stats.add({.start_s = 0.0, .draw_ms = 100.0});
    stats.add({.start_s = 0.5, .draw_ms = 100.0, .interval_ms = 500.0});
    // A settled view shown again three times, each in a millisecond: not drawing.
    for (int i = 0; i < 3; ++i) stats.add({.start_s = 1.0 + i, .draw_ms = 1.0, .drawn = false});
    EXPECT_EQ(stats.total(), 5);
    EXPECT_EQ(stats.frames().size(), 2u);
    const std::string s = stats.summary();
    EXPECT_NE(s.find("2 frames in 0.6 s: 3.33 frames/s; draw ms p50 100.0"), std::string::npos)
        << s;
    EXPECT_NE(s.find("3 more shown again undrawn"), std::string::npos) << s;
}

TEST(FrameStats, MovingFramesAndStillViewsAreTimedApart) {
    FrameStats stats;
    // Two moving frames of 30 ms, then a still view's first frame (40 ms) and two bands of
    // 100 ms: every frame's p50 is the third of five by nearest rank, 40; the moving ones' the
    // first of two, 30; the still view's the second of three, 100.
    for (int i = 0; i < 2; ++i) stats.add({.start_s = 0.1 * i, .draw_ms = 30.0});
    stats.add({.start_s = 0.2, .draw_ms = 40.0, .still = 0});
    stats.add({.start_s = 0.3, .draw_ms = 100.0, .still = 1});
    stats.add({.start_s = 0.4, .draw_ms = 100.0, .still = 1});
    const std::string s = stats.summary();
    EXPECT_NE(s.find("draw ms p50 40.0"), std::string::npos) << s;
    EXPECT_NE(s.find("moving (2) draw ms p50 30.0 p90 30.0"), std::string::npos) << s;
    EXPECT_NE(s.find("still view (3) draw ms p50 100.0 p90 100.0 p99 100.0 max 100.0"),
              std::string::npos)
        << s;
    // Frames of one kind only: no split.
    FrameStats moving_only;
    moving_only.add({.draw_ms = 30.0});
    EXPECT_EQ(moving_only.summary().find("moving ("), std::string::npos);
}

TEST(FrameStats, CsvToAnUnwritablePlaceIsAnError) {
    FrameStats stats;
    stats.add({});
    std::string error;
    EXPECT_FALSE(stats.write_csv("/nonexistent-dir/frames.csv", error));
    EXPECT_NE(error.find("/nonexistent-dir/frames.csv"), std::string::npos);
}

}  // namespace
}  // namespace gem::kiosk

namespace gem::kiosk {
namespace {

TEST(FrameStats, BoundedStatsKeepTheNewestFramesAndCountThemAll) {
    FrameStats stats(3);
    for (int i = 0; i < 5; ++i) stats.add({.start_s = double(i), .draw_ms = 10.0 * (i + 1)});
    EXPECT_EQ(stats.total(), 5);
    ASSERT_EQ(stats.frames().size(), 3u);
    EXPECT_EQ(stats.frames().front().start_s, 2.0);  // frames 2, 3, 4 remain
    EXPECT_EQ(stats.frames().back().draw_ms, 50.0);
    // The summary says which frames it describes: 3 frames from 2 s to 4.05 s.
    EXPECT_NE(stats.summary().find("5 frames, the last 3 frames in 2.0 s"), std::string::npos)
        << stats.summary();
}

TEST(FrameStats, FramesDrawnWhileTheProbeMeasuredAreCountedApart) {
    FrameStats stats;
    // Two slow frames while the probe measured, then two of the chosen method: 0.5 s apart,
    // each 20 ms, so 2 / 0.52 = 3.85 frames/s and a p50 of 20 ms.
    stats.add({.start_s = 0.0, .draw_ms = 300.0, .probing = true});
    stats.add({.start_s = 0.4, .draw_ms = 300.0, .probing = true});
    stats.add({.start_s = 1.0, .draw_ms = 20.0});
    stats.add({.start_s = 1.5, .draw_ms = 20.0, .interval_ms = 500.0});
    EXPECT_EQ(stats.total(), 4);
    const std::string s = stats.summary();
    EXPECT_NE(s.find("2 frames in 0.5 s: 3.85 frames/s; draw ms p50 20.0"), std::string::npos) << s;
    EXPECT_NE(s.find("2 more drawn while the method probe measured"), std::string::npos) << s;
    FrameStats only_probing;
    only_probing.add({.start_s = 0.0, .draw_ms = 300.0, .probing = true});
    EXPECT_EQ(only_probing.summary(), "1 frames, all drawn while the method probe measured");
}

}  // namespace
}  // namespace gem::kiosk
