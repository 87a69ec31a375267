#include "service/watchdog_policy.hpp"

namespace gem::kiosk {

WatchdogPolicy::WatchdogPolicy(double interval_s)
    : period_s_(interval_s > 0.0 ? interval_s / 2.0 : 0.0) {}

void WatchdogPolicy::frame_presented(double /*now_s*/) {
    progressed_ = true;
}

void WatchdogPolicy::set_frames_expected(bool expected) {
    // The display just came (back): give it until one interval after the next ping to show
    // its first frame, instead of holding the ping back from the moment of the switch.
    if (expected && !frames_expected_) progressed_ = true;
    frames_expected_ = expected;
}

bool WatchdogPolicy::should_ping(double now_s) const {
    return enabled() && now_s >= last_ping_s_ + period_s_ && progress_allows_ping();
}

void WatchdogPolicy::pinged(double now_s) {
    last_ping_s_ = now_s;
    progressed_ = false;
}

double WatchdogPolicy::next_ping_s() const {
    if (!enabled() || !progress_allows_ping()) return std::numeric_limits<double>::infinity();
    return last_ping_s_ + period_s_;
}

}  // namespace gem::kiosk
