#pragma once
// render.method = "auto": the kiosk measures itself once at start and keeps the most accurate
// rendering method that holds its frame rate. This file is the choice alone, free of GL, so it
// is tested on numbers: the candidates in order from the most accurate to the cheapest, each
// with the frame times a short probe measured, and the frame budget. method_probe_run.hpp does
// the measuring.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gpu/frame_renderer.hpp"
#include "gpu/stone_method.hpp"

namespace gem::kiosk {

// One way to draw the stone, as the probe tries it: a rung of a method's registry entry.
using MethodCandidate = gpu::MethodRung;

// The ladder the probe walks: each method's rungs in the registry's order (most accurate
// first). Today: trace with exact fire (each channel at its own index, for a database that
// stores dispersion; without it the first two rungs draw the same, and the first is left
// out), trace (exact at every view: the facet walk; fire to first order), table blend at the
// needed level, table nearest, table nearest one level lower (only when `needed_level` > 0),
// phong.
std::vector<MethodCandidate> method_ladder(int needed_level, bool dispersion = false);
// The rungs of `ladder` whose methods can draw a stone without ray-tables and refract (a
// design's: the trace's).
std::vector<MethodCandidate> rungs_without_tables(std::vector<MethodCandidate> ladder);

// The statistic a candidate is judged by: the 90th percentile of its frame times (nearest
// rank, so it is one of the measured values). A median would pass a method that streams a new
// view every few frames and misses the budget on those frames: a visible stutter in every
// turn. p90 over a handful of frames is close to the slowest frame without being set by one
// outlier in a run of ten or more. Non-finite and negative times (a failed frame) are dropped;
// with none left the candidate has no statistic.
std::optional<double> frame_time_statistic_ms(std::vector<double> frame_ms);
inline constexpr double kFrameTimeQuantile = 0.9;

struct MethodChoice {
    std::size_t index = 0;                            // into the candidates
    bool fits = false;                                // its statistic is within the budget
    std::vector<std::optional<double>> statistic_ms;  // per candidate, as judged
    double budget_ms = 0.0;                           // after headroom
    bool valid = false;  // false: no candidate had a usable measurement
};

// budget_ms = headroom / target rate: the share of a frame period the stone may take (the rest
// goes to compositing, the cross-fade and presenting). The FIRST candidate whose statistic is
// within the budget wins. If none is, a stand-in among the first `fallbacks` candidates (the
// ladder passes its refractive rungs, so a machine too slow for every method still shows a
// refracting stone, not phong's flat one, which is chosen only when it alone holds the rate):
// the first of them within kNearFastest of the fastest of them. Missing the rate either way, a
// frame a few per cent longer is not seen, a coarser or approximate picture is. A candidate
// without a usable measurement is never chosen; when none of the fallbacks has one, the
// fastest of the rest is; when no candidate has one the choice is invalid and index points at
// the last, cheapest candidate.
inline constexpr double kNearFastest = 1.25;
MethodChoice choose_method(const std::vector<std::vector<double>>& frame_ms_per_candidate,
                           double budget_ms, std::size_t fallbacks = SIZE_MAX);
// The candidates that may stand in when none holds the rate: the rungs of the methods that
// refract (every one but the baseline's, which come last).
std::size_t refractive_rungs(const std::vector<MethodCandidate>& ladder);

// The frame budget in ms: headroom × 1000 / rate, rate = render.frame_rate_hz when positive,
// else the display's refresh; no positive rate (a headless display drawing as fast as it can)
// gives an unlimited budget, so the most accurate candidate wins.
double frame_budget_ms(double frame_rate_hz, double refresh_hz, double headroom);

// One line naming every candidate, its statistic and the choice, for the journal.
std::string describe_choice(const std::vector<MethodCandidate>& candidates,
                            const MethodChoice& choice);

}  // namespace gem::kiosk
