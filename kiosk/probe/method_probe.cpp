#include "probe/method_probe.hpp"

#include "service/frame_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace gem::kiosk {

namespace {

bool refracts(const MethodCandidate& c) {
    const gpu::MethodEntry* method = gpu::find_stone_method(c.method);
    return method != nullptr && method->refracts;
}

}  // namespace

std::vector<MethodCandidate> method_ladder(int needed_level, bool dispersion) {
    return gpu::method_rungs({needed_level, dispersion});
}

std::vector<MethodCandidate> rungs_without_tables(std::vector<MethodCandidate> ladder) {
    std::erase_if(ladder, [](const MethodCandidate& c) {
        const gpu::MethodEntry* method = gpu::find_stone_method(c.method);
        return method == nullptr || method->needs_database || !method->refracts;
    });
    return ladder;
}

std::optional<double> frame_time_statistic_ms(std::vector<double> frame_ms) {
    std::erase_if(frame_ms, [](double t) { return !std::isfinite(t) || t < 0.0; });
    if (frame_ms.empty()) return std::nullopt;
    return quantile(std::move(frame_ms), kFrameTimeQuantile);
}

std::size_t refractive_rungs(const std::vector<MethodCandidate>& ladder) {
    return static_cast<std::size_t>(std::count_if(ladder.begin(), ladder.end(), refracts));
}

MethodChoice choose_method(const std::vector<std::vector<double>>& frame_ms_per_candidate,
                           double budget_ms, std::size_t fallbacks) {
    MethodChoice choice;
    choice.budget_ms = budget_ms;
    const std::size_t n = frame_ms_per_candidate.size();
    choice.index = n > 0 ? n - 1 : 0;
    for (std::size_t i = 0; i < n; ++i) {
        choice.statistic_ms.push_back(frame_time_statistic_ms(frame_ms_per_candidate[i]));
    }
    for (std::size_t i = 0; i < n; ++i) {
        const auto& s = choice.statistic_ms[i];
        if (s && *s <= budget_ms) {
            choice.index = i;
            choice.fits = true;
            choice.valid = true;
            return choice;
        }
    }
    // The fastest in [begin, end), strict so that the earlier, more accurate one keeps a tie;
    // then the first in [begin, end) within kNearFastest of it.
    auto stand_in = [&](std::size_t begin, std::size_t end) {
        std::optional<std::size_t> fastest;
        for (std::size_t i = begin; i < end; ++i) {
            const auto& s = choice.statistic_ms[i];
            if (s && (!fastest || *s < *choice.statistic_ms[*fastest])) fastest = i;
        }
        if (!fastest) return fastest;
        const double near = kNearFastest * *choice.statistic_ms[*fastest];
        for (std::size_t i = begin; i < end; ++i) {
            const auto& s = choice.statistic_ms[i];
            if (s && *s <= near) return std::optional<std::size_t>(i);
        }
        return fastest;
    };
    const std::size_t split = std::min(fallbacks, n);
    std::optional<std::size_t> pick = stand_in(0, split);
    if (!pick) pick = stand_in(split, n);
    if (pick) {
        choice.index = *pick;
        choice.valid = true;
    }
    return choice;
}

double frame_budget_ms(double frame_rate_hz, double refresh_hz, double headroom) {
    const double rate = frame_rate_hz > 0.0 ? frame_rate_hz : refresh_hz;
    if (!(rate > 0.0) || !std::isfinite(rate)) return std::numeric_limits<double>::infinity();
    return headroom * 1000.0 / rate;
}

std::string describe_choice(const std::vector<MethodCandidate>& candidates,
                            const MethodChoice& choice) {
    std::string line;
    char number[48];
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        if (!line.empty()) line += ", ";
        line += candidates[i].name + " ";
        const bool measured = i < choice.statistic_ms.size() && choice.statistic_ms[i];
        if (measured) {
            std::snprintf(number, sizeof number, "%.1f ms", *choice.statistic_ms[i]);
            line += number;
        } else {
            line += "not measured";
        }
    }
    if (std::isfinite(choice.budget_ms)) {
        std::snprintf(number, sizeof number, "%.1f ms", choice.budget_ms);
    } else {
        std::snprintf(number, sizeof number, "unlimited");
    }
    std::string chosen = choice.index < candidates.size() ? candidates[choice.index].name : "?";
    return "render.method auto: p90 frame times " + line + "; budget " + number + "; using " +
           chosen;
}

}  // namespace gem::kiosk
