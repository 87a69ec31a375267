// render.method = "auto": the choice among measured candidates. Every expected value is worked
// by hand from the numbers in the test: nearest-rank p90 = the ceil(0.9 n)-th smallest value,
// budget = headroom × 1000 / rate.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/stone_method.hpp"
#include "probe/method_probe.hpp"

namespace gem::kiosk {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(MethodProbe, P90IsTheNearestRankValue) {
    // 10 values: ceil(9) = 9th smallest; 20 values: 18th; 1 value: itself.
    EXPECT_EQ(frame_time_statistic_ms({10, 1, 9, 2, 8, 3, 7, 4, 6, 5}), 9.0);
    std::vector<double> twenty;
    for (int i = 20; i >= 1; --i) twenty.push_back(i);
    EXPECT_EQ(frame_time_statistic_ms(twenty), 18.0);
    EXPECT_EQ(frame_time_statistic_ms({4.5}), 4.5);
    // 4 values: ceil(3.6) = 4th, the slowest (one slow frame in four is a stutter).
    EXPECT_EQ(frame_time_statistic_ms({1, 1, 1, 30}), 30.0);
}

TEST(MethodProbe, BadFrameTimesAreDropped) {
    // Left: 5 and 7; ceil(1.8) = 2nd smallest.
    EXPECT_EQ(frame_time_statistic_ms({5, kNaN, -1, kInf, 7}), 7.0);
    EXPECT_FALSE(frame_time_statistic_ms({kNaN, -2.0}).has_value());
    EXPECT_FALSE(frame_time_statistic_ms({}).has_value());
}

TEST(MethodProbe, BudgetIsHeadroomOverTheTargetRate) {
    EXPECT_NEAR(frame_budget_ms(0, 60, 0.8), 0.8 * 1000.0 / 60.0, 1e-12);  // 13.33 ms
    // A configured rate outranks the display's refresh.
    EXPECT_NEAR(frame_budget_ms(30, 60, 0.8), 0.8 * 1000.0 / 30.0, 1e-12);  // 26.67 ms
    EXPECT_NEAR(frame_budget_ms(0, 50, 1.0), 20.0, 1e-12);
    EXPECT_TRUE(std::isinf(frame_budget_ms(0, 0, 0.8)));  // no rate: no budget
}

TEST(MethodProbe, TheFirstCandidateThatFitsWinsEvenIfALaterOneIsFaster) {
    const MethodChoice c = choose_method({{20, 21}, {12, 13}, {5, 5}}, 15.0);
    EXPECT_TRUE(c.valid);
    EXPECT_TRUE(c.fits);
    EXPECT_EQ(c.index, 1u);
    EXPECT_EQ(c.statistic_ms[0], 21.0);
    EXPECT_EQ(c.statistic_ms[1], 13.0);
}

TEST(MethodProbe, ExactlyOnTheBudgetFits) {
    const MethodChoice c = choose_method({{16, 16}, {10}}, 16.0);
    EXPECT_TRUE(c.fits);
    EXPECT_EQ(c.index, 0u);
}

TEST(MethodProbe, AMedianUnderBudgetWithSlowStreamingFramesDoesNotFit) {
    // Median 10 ms, but 2 of 10 frames at 40 ms: p90 (9th of 10) = 40 > 15.
    const MethodChoice c = choose_method({{10, 10, 10, 10, 10, 10, 10, 10, 40, 40}, {14}}, 15.0);
    EXPECT_EQ(c.index, 1u);
    EXPECT_TRUE(c.fits);
}

TEST(MethodProbe, NoneFitsTakesTheFastestAndSaysSo) {
    const MethodChoice c = choose_method({{300}, {150}, {200}}, 13.3);
    EXPECT_TRUE(c.valid);
    EXPECT_FALSE(c.fits);
    EXPECT_EQ(c.index, 1u);
}

TEST(MethodProbe, NoneFitsPrefersTheMoreAccurateWhenItIsNearlyAsFast) {
    // Fastest 100 ms; 1.25 × 100 = 125: the first within it is the 120 ms one, not the fastest.
    EXPECT_EQ(choose_method({{200}, {120}, {110}, {100}}, 13.3).index, 1u);
    // Exactly on the bound counts as near; just over it does not.
    EXPECT_EQ(choose_method({{125}, {100}}, 13.3).index, 0u);
    EXPECT_EQ(choose_method({{126}, {100}}, 13.3).index, 1u);
    // As measured at 1080p on the build machine: trace 57.3 is within 1.25 × 51.8 of table
    // one level down, so the exact picture stands in; phong (32.3) is no fallback.
    EXPECT_EQ(choose_method({{75.1}, {57.3}, {76.0}, {71.2}, {51.8}, {32.3}}, 13.3, 5).index, 1u);
}

TEST(MethodProbe, NoneFitsNeverFallsBackToTheFlatBaseline) {
    // Phong (last, 80 ms) is the fastest but not among the 2 fallbacks: the faster of those.
    const MethodChoice c = choose_method({{300}, {150}, {80}}, 13.3, 2);
    EXPECT_FALSE(c.fits);
    EXPECT_EQ(c.index, 1u);
    // Phong that holds the rate is still chosen.
    EXPECT_EQ(choose_method({{300}, {150}, {10}}, 13.3, 2).index, 2u);
    // Fallbacks without measurements: the fastest of the rest.
    EXPECT_EQ(choose_method({{kNaN}, {}, {80}}, 13.3, 2).index, 2u);
    // The ladder's fallbacks are its refractive rungs: all but phong.
    EXPECT_EQ(refractive_rungs(method_ladder(2, true)), 5u);
    EXPECT_EQ(refractive_rungs(method_ladder(0)), 3u);
}

TEST(MethodProbe, ATieAmongTooSlowCandidatesKeepsTheMoreAccurate) {
    const MethodChoice c = choose_method({{90}, {40}, {40}}, 10.0);
    EXPECT_FALSE(c.fits);
    EXPECT_EQ(c.index, 1u);
}

TEST(MethodProbe, ACandidateWithoutUsableTimesIsNeverChosen) {
    // The first has only failed frames; the second is unmeasured (empty).
    const MethodChoice c = choose_method({{kNaN, kNaN}, {}, {50}}, 10.0);
    EXPECT_FALSE(c.statistic_ms[0].has_value());
    EXPECT_FALSE(c.statistic_ms[1].has_value());
    EXPECT_TRUE(c.valid);
    EXPECT_EQ(c.index, 2u);
    const MethodChoice none = choose_method({{kNaN}, {}}, 10.0);
    EXPECT_FALSE(none.valid);
    EXPECT_FALSE(none.fits);
    EXPECT_EQ(none.index, 1u);  // the cheapest
}

TEST(MethodProbe, AnUnlimitedBudgetTakesTheMostAccurate) {
    const MethodChoice c = choose_method({{500}, {1}}, kInf);
    EXPECT_TRUE(c.fits);
    EXPECT_EQ(c.index, 0u);
}

TEST(MethodProbe, TheLadderRunsFromTheMostAccurateToPhong) {
    const std::vector<MethodCandidate> top = method_ladder(2);
    ASSERT_EQ(top.size(), 5u);
    EXPECT_EQ(top[0].method, "trace");  // exact at every view
    EXPECT_EQ(top[1].method, "table");
    EXPECT_TRUE(top[1].blend);
    EXPECT_EQ(top[1].max_level, -1);
    EXPECT_FALSE(top[2].blend);
    EXPECT_EQ(top[2].max_level, -1);
    EXPECT_FALSE(top[3].blend);
    EXPECT_EQ(top[3].max_level, 1);  // one below the needed level 2
    EXPECT_EQ(top[4].method, "phong");
    // A database with dispersion gets exact fire first; the rest is the same ladder.
    const std::vector<MethodCandidate> fire = method_ladder(2, true);
    ASSERT_EQ(fire.size(), 6u);
    EXPECT_EQ(fire[0].method, "trace");
    EXPECT_TRUE(fire[0].exact_fire);
    EXPECT_FALSE(fire[1].exact_fire);
    EXPECT_EQ(fire[1].method, "trace");
    EXPECT_EQ(fire[5].method, "phong");
    // At level 0 there is nothing coarser: no capped rung.
    const std::vector<MethodCandidate> bottom = method_ladder(0);
    ASSERT_EQ(bottom.size(), 4u);
    EXPECT_EQ(bottom[3].method, "phong");
}

// The ladder names its methods as the registry does, so each rung is a method this build has.
TEST(MethodProbe, EveryRungIsARegisteredStoneMethod) {
    for (const MethodCandidate& c : method_ladder(2, true)) {
        EXPECT_NE(gpu::find_stone_method(c.method), nullptr) << c.name;
    }
}

TEST(MethodProbe, TheLogLineNamesEveryCandidateAndTheChoice) {
    const std::vector<MethodCandidate> ladder = method_ladder(0);
    const MethodChoice c = choose_method({{31}, {20}, {12.3}, {}}, 15.0);
    const std::string line = describe_choice(ladder, c);
    EXPECT_NE(line.find("trace 31.0 ms"), std::string::npos) << line;
    EXPECT_NE(line.find("table blend 20.0 ms"), std::string::npos) << line;
    EXPECT_NE(line.find("table nearest 12.3 ms"), std::string::npos) << line;
    EXPECT_NE(line.find("phong not measured"), std::string::npos) << line;
    EXPECT_NE(line.find("budget 15.0 ms"), std::string::npos) << line;
    EXPECT_NE(line.find("using table nearest"), std::string::npos) << line;
}

}  // namespace
}  // namespace gem::kiosk
