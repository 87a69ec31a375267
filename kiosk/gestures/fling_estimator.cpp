#include "gestures/fling_estimator.hpp"

#include <algorithm>
#include <cassert>

namespace gem::kiosk {

namespace {

// Running sums for a least-squares line x = a + v t, in time relative to the window's end so that
// the sums stay small whatever the clock's epoch.
struct LineFit {
    double n = 0.0;
    double t = 0.0;
    double tt = 0.0;
    glm::dvec2 x{0.0};
    glm::dvec2 tx{0.0};

    void add(double time, glm::dvec2 value) {
        n += 1.0;
        t += time;
        tt += time * time;
        x += value;
        tx += time * value;
    }
    glm::dvec2 slope() const {
        const double denominator = n * tt - t * t;
        // Samples closer together than a microsecond carry no speed.
        if (n < 2.0 || denominator <= 1e-12 * n * n) return glm::dvec2(0.0);
        return (n * tx - t * x) / denominator;
    }
};

}  // namespace

FlingEstimator::FlingEstimator(double window_s) : window_s_(window_s) {
    assert(window_s > 0.0);
}

void FlingEstimator::restart(double time_s, glm::dvec2 turn_deg) {
    samples_.clear();
    samples_.push_back({time_s, turn_deg});
}

void FlingEstimator::add(double time_s, glm::dvec2 turn_deg) {
    samples_.push_back({time_s, turn_deg});
    // Keep one sample at or before the window's start, for the interpolation there.
    const double start = time_s - window_s_;
    std::size_t drop = 0;
    while (drop + 1 < samples_.size() && samples_[drop + 1].time_s <= start) ++drop;
    samples_.erase(samples_.begin(), samples_.begin() + static_cast<std::ptrdiff_t>(drop));
}

glm::dvec2 FlingEstimator::velocity(double lift_time_s) const {
    if (samples_.empty()) return glm::dvec2(0.0);
    const Sample& last = samples_.back();
    double end = lift_time_s;
    if (samples_.size() >= 2) {
        const double interval = last.time_s - samples_[samples_.size() - 2].time_s;
        end = std::max(last.time_s, lift_time_s - interval);
    }
    const double start = end - window_s_;
    LineFit fit;
    for (std::size_t i = 0; i < samples_.size(); ++i) {
        const Sample& s = samples_[i];
        if (s.time_s > start) {
            fit.add(s.time_s - end, s.turn_deg);
            continue;
        }
        // A sample at or before the window's start: interpolate toward the next one (or hold
        // it, when it is the last), but only from the last such sample.
        if (i + 1 < samples_.size() && samples_[i + 1].time_s <= start) continue;
        glm::dvec2 at_start = s.turn_deg;
        if (i + 1 < samples_.size()) {
            const Sample& next = samples_[i + 1];
            const double f = (start - s.time_s) / (next.time_s - s.time_s);
            at_start = s.turn_deg + f * (next.turn_deg - s.turn_deg);
        }
        fit.add(-window_s_, at_start);
    }
    if (end > last.time_s) fit.add(0.0, last.turn_deg);
    return fit.slope();
}

}  // namespace gem::kiosk
