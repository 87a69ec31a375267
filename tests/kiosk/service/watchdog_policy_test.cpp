// The watchdog rule on its own (kiosk/service/watchdog_policy.hpp), with times chosen by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "service/watchdog_policy.hpp"

namespace gem::kiosk {
namespace {

TEST(WatchdogPolicy, OffWithoutAnInterval) {
    WatchdogPolicy policy(0.0);
    policy.frame_presented(1.0);
    EXPECT_FALSE(policy.enabled());
    EXPECT_FALSE(policy.should_ping(100.0));
    EXPECT_TRUE(std::isinf(policy.next_ping_s()));
}

TEST(WatchdogPolicy, PingsOnlyAfterAFrameAndHalfAnIntervalApart) {
    WatchdogPolicy policy(10.0);  // W = 10 s: pings at least 5 s apart
    EXPECT_DOUBLE_EQ(policy.period_s(), 5.0);
    EXPECT_FALSE(policy.should_ping(0.0));  // frames expected, none yet
    policy.frame_presented(0.5);
    EXPECT_TRUE(policy.should_ping(0.5));
    policy.pinged(0.5);
    policy.frame_presented(1.0);
    EXPECT_FALSE(policy.should_ping(5.4));  // 4.9 s after the ping
    EXPECT_DOUBLE_EQ(policy.next_ping_s(), 5.5);
    EXPECT_TRUE(policy.should_ping(5.5));
    policy.pinged(5.5);
    // Stalled: no frame since the ping, so no ping however long one waits, and nothing to
    // wake up for.
    EXPECT_FALSE(policy.should_ping(11.0));
    EXPECT_FALSE(policy.should_ping(60.0));
    EXPECT_TRUE(std::isinf(policy.next_ping_s()));
    policy.frame_presented(61.0);
    EXPECT_TRUE(policy.should_ping(61.0));
}

TEST(WatchdogPolicy, NoFramesExpectedPingsOnLivenessAlone) {
    WatchdogPolicy policy(10.0);
    policy.set_frames_expected(false);
    EXPECT_TRUE(policy.should_ping(0.0));
    policy.pinged(0.0);
    EXPECT_FALSE(policy.should_ping(4.0));
    EXPECT_DOUBLE_EQ(policy.next_ping_s(), 5.0);
    EXPECT_TRUE(policy.should_ping(5.0));
    policy.pinged(5.0);
    // Frames expected again: the switch counts once as progress, then frames are needed.
    policy.set_frames_expected(true);
    EXPECT_TRUE(policy.should_ping(10.0));
    policy.pinged(10.0);
    EXPECT_FALSE(policy.should_ping(15.0));
    EXPECT_FALSE(policy.should_ping(40.0));
}

TEST(WatchdogPolicy, ExpectedAgainWithoutHavingStoppedGrantsNothing) {
    WatchdogPolicy policy(10.0);
    policy.frame_presented(0.0);
    policy.pinged(0.0);
    policy.set_frames_expected(true);  // already expected: no free ping
    EXPECT_FALSE(policy.should_ping(6.0));
}

// Simulates a main loop ticking every 10 ms; returns the times of the pings.
std::vector<double> simulate(WatchdogPolicy& policy, const std::vector<double>& frames,
                             double end_s) {
    std::vector<double> pings;
    std::size_t next_frame = 0;
    for (long step = 0; step * 0.01 <= end_s; ++step) {
        const double now = step * 0.01;
        while (next_frame < frames.size() && frames[next_frame] <= now)
            policy.frame_presented(frames[next_frame++]);
        if (policy.should_ping(now)) {
            policy.pinged(now);
            pings.push_back(now);
        }
    }
    return pings;
}

// Frames less than W apart never leave W without a ping (header: the next ping comes by
// max(t0 + W/2, first frame after t0) < t0 + W).
TEST(WatchdogPolicy, FramesLessThanAnIntervalApartKeepItAlive) {
    WatchdogPolicy policy(10.0);
    std::vector<double> frames;
    for (double t = 0.0; t < 200.0; t += 9.7) frames.push_back(t);
    const std::vector<double> pings = simulate(policy, frames, 200.0);
    ASSERT_GE(pings.size(), 20u);  // 200 s / 9.7 s: a ping per frame
    for (std::size_t i = 1; i < pings.size(); ++i) EXPECT_LT(pings[i] - pings[i - 1], 10.0) << i;
}

// A picture frozen from t = 100 s: the last ping comes no later than W/2 after the last frame
// and none follows, so systemd restarts the service by 100 + 1.5 W.
TEST(WatchdogPolicy, AFrozenPictureStopsThePings) {
    WatchdogPolicy policy(10.0);
    std::vector<double> frames;
    for (double t = 0.0; t <= 100.0; t += 1.0 / 60.0) frames.push_back(t);
    const std::vector<double> pings = simulate(policy, frames, 300.0);
    ASSERT_FALSE(pings.empty());
    EXPECT_GE(pings.back(), 95.0);
    EXPECT_LE(pings.back(), 100.0 + 5.0 + 0.01);
}

}  // namespace
}  // namespace gem::kiosk
