#include "gestures/attract_mode.hpp"

#include <algorithm>
#include <cmath>

namespace gem::kiosk {

namespace {

// Moves `due_s` past `now_s` in whole periods; true when it was due.
bool take_due(double now_s, double period_s, double& due_s) {
    if (period_s <= 0.0 || now_s < due_s) return false;
    due_s += period_s * (std::floor((now_s - due_s) / period_s) + 1.0);
    return true;
}

}  // namespace

void AttractMode::begin(double time_s, const ViewState& view) {
    active_ = true;
    restart_ease(time_s, view);
    next_preset_s_ = time_s + options_.attract_preset_s;
    next_stone_s_ = time_s + options_.attract_stone_s;
}

void AttractMode::restart_ease(double time_s, const ViewState& view) {
    ease_start_s_ = time_s;
    ease_start_view_ = view;
}

ViewState AttractMode::advance(double now_s, const ViewState& target,
                               std::vector<GestureAction>& actions) {
    const double t = std::max(0.0, now_s - ease_start_s_);
    const double u =
        options_.attract_ease_s > 0.0 ? std::min(1.0, t / options_.attract_ease_s) : 1.0;
    const double s = u * u * (3.0 - 2.0 * u);
    const ViewState& from = ease_start_view_;
    ViewState view;
    view.azimuth_deg = wrap_degrees(from.azimuth_deg + options_.attract_deg_per_s * t);
    view.elevation_deg = from.elevation_deg + (target.elevation_deg - from.elevation_deg) * s;
    view.roll_deg =
        wrap_degrees(from.roll_deg + angle_difference_deg(target.roll_deg, from.roll_deg) * s);
    view.zoom = from.zoom * std::pow(target.zoom / from.zoom, s);

    if (take_due(now_s, options_.attract_stone_s, next_stone_s_)) {
        actions.push_back(GestureAction::next_stone);
    }
    if (take_due(now_s, options_.attract_preset_s, next_preset_s_)) {
        actions.push_back(GestureAction::next_preset);
    }
    return view;
}

}  // namespace gem::kiosk
