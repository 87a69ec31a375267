#include "gestures/gesture_controller.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>
#include <variant>

#include <glm/geometric.hpp>

#include "gestures/contact_motion.hpp"
#include "gestures/turntable.hpp"

namespace gem::kiosk {

namespace {

// Two fingers closer than this to their midpoint (a thumb and finger pinched shut, or a
// panel reporting one finger twice) give no usable zoom or twist.
constexpr double kMinSpreadPx = 8.0;

// std::clamp requires lo <= hi; a config with min_zoom > max_zoom should not be undefined.
double clamp_between(double value, double lo, double hi) {
    return std::min(std::max(value, lo), hi);
}

}  // namespace

GestureController::GestureController(const GestureOptions& options, const ViewState& start_view)
    : options_(options),
      fling_(options.fling_window_s > 0.0 ? options.fling_window_s : 0.08),
      tap_(options.tap_max_s, options.tap_max_move_px),
      attract_(options) {
    reset_view(start_view);
    start_view_ = view_;
}

void GestureController::set_picture_size(glm::dvec2 size_px) {
    picture_size_ = size_px;
}

void GestureController::set_elevation_limits(double min_deg, double max_deg) {
    assert(min_deg <= max_deg);
    min_elevation_deg_ = std::max(-90.0, min_deg);
    max_elevation_deg_ = std::min(90.0, max_deg);
    view_.elevation_deg =
        clamp_between(view_.elevation_deg, min_elevation_deg_, max_elevation_deg_);
}

void GestureController::on_event(const InputEvent& event) {
    std::visit(
        [this](const auto& e) {
            if constexpr (std::is_same_v<std::decay_t<decltype(e)>, TouchFrame>) {
                on_touch_frame(e);
            } else {
                on_wheel(e);
            }
        },
        event);
}

void GestureController::advance(double now_s) {
    if (!clock_started_) {
        clock_started_ = true;
        now_s_ = now_s;
        last_input_s_ = now_s;
        return;
    }
    if (now_s <= now_s_) return;
    enter_attract_if_idle(now_s);
    if (attract_.active()) {
        view_ = attract_.advance(now_s, attract_target(), actions_);
        view_.elevation_deg =
            clamp_between(view_.elevation_deg, min_elevation_deg_, max_elevation_deg_);
        view_.zoom = clamp_between(view_.zoom, options_.min_zoom, options_.max_zoom);
    } else {
        run_inertia(now_s);
    }
    now_s_ = now_s;
}

std::vector<GestureAction> GestureController::take_actions() {
    std::vector<GestureAction> taken;
    taken.swap(actions_);
    return taken;
}

void GestureController::reset_view(const ViewState& view) {
    view_.azimuth_deg = wrap_degrees(view.azimuth_deg);
    view_.elevation_deg = clamp_between(view.elevation_deg, min_elevation_deg_, max_elevation_deg_);
    view_.roll_deg = wrap_degrees(view.roll_deg);
    view_.zoom = clamp_between(view.zoom, options_.min_zoom, options_.max_zoom);
    inertia_.stop();
    if (attract_.active()) attract_.restart_ease(now_s_, view_);
}

void GestureController::on_touch_frame(const TouchFrame& frame) {
    advance(frame.time_s);
    last_input_s_ = now_s_;
    const bool was_touching = !contacts_.empty();
    const bool touching = !frame.contacts.empty();
    // The touch that wakes the kiosk takes over from attract mode's view as it is now; it is
    // not also a tap (the shopper meant to stop the show, not to change the stone).
    const bool woke = touching && attract_.active();
    if (woke) attract_.end();
    if (touching) inertia_.stop();
    if (touching && !was_touching) tap_.begin(frame.time_s);
    if (woke) tap_.disqualify();
    tap_.update(frame);
    move_contacts(contacts_, frame, woke);
    if (was_touching && !touching) touch_up(frame.time_s);
    contacts_ = frame.contacts;
}

void GestureController::on_wheel(const WheelStep& wheel) {
    advance(wheel.time_s);
    last_input_s_ = now_s_;
    if (attract_.active()) attract_.end();
    scale_zoom(std::pow(options_.wheel_zoom_step, wheel.steps));
}

void GestureController::move_contacts(const std::vector<Contact>& before, const TouchFrame& after,
                                      bool anchor) {
    const ContactMotion motion = contact_motion(before, after.contacts, kMinSpreadPx);
    const bool same_single_finger =
        !anchor && before.size() == 1 && after.contacts.size() == 1 && motion.common == 1;
    if (same_single_finger) {
        if (picture_size_.y > 0.0) {
            const double degrees_per_px = options_.degrees_per_picture_height / picture_size_.y;
            const glm::dvec2 d = turntable_turn(motion.translation, view_.roll_deg, degrees_per_px);
            drag_turn_deg_ += d;
            turn(d);
        }
        fling_.add(after.time_s, drag_turn_deg_);
        return;
    }
    // A single finger from here on (the first one down, or the one left of a pinch): its drag
    // and its fling history start here.
    if (after.contacts.size() == 1) fling_.restart(after.time_s, drag_turn_deg_);
    if (!anchor && motion.spread_measurable) {
        scale_zoom(motion.scale);
        view_.roll_deg = wrap_degrees(view_.roll_deg + motion.rotation_deg);
    }
}

void GestureController::touch_up(double time_s) {
    switch (tap_.end(time_s)) {
        case TapKind::one_finger:
            push_tap_action(options_.tap);
            return;
        case TapKind::two_finger:
            push_tap_action(options_.two_finger_tap);
            return;
        case TapKind::none:
            break;
    }
    // Only a one-finger drag flings; a pinch or twist ends where the fingers left it.
    if (contacts_.size() != 1 || attract_.active()) return;
    glm::dvec2 velocity = fling_.velocity(time_s);
    const double speed = glm::length(velocity);
    if (!(speed >= options_.fling_min_deg_per_s)) return;
    if (speed > options_.fling_max_deg_per_s) velocity *= options_.fling_max_deg_per_s / speed;
    inertia_.start(velocity, options_.inertia_half_life_s);
}

void GestureController::turn(glm::dvec2 turn_deg) {
    view_.azimuth_deg = wrap_degrees(view_.azimuth_deg + turn_deg.x);
    const double wanted = view_.elevation_deg + turn_deg.y;
    view_.elevation_deg = clamp_between(wanted, min_elevation_deg_, max_elevation_deg_);
    // A spin that runs into the band's edge goes on about the vertical axis alone.
    if (view_.elevation_deg != wanted) inertia_.stop_elevation();
}

void GestureController::scale_zoom(double factor) {
    view_.zoom = clamp_between(view_.zoom * factor, options_.min_zoom, options_.max_zoom);
}

void GestureController::run_inertia(double until_s) {
    if (!inertia_.active() || until_s <= now_s_) return;
    turn(inertia_.advance(until_s - now_s_));
}

void GestureController::enter_attract_if_idle(double now_s) {
    if (attract_.active() || options_.idle_s <= 0.0) return;
    const double begin_s = std::max(last_input_s_ + options_.idle_s, now_s_);
    if (now_s < begin_s) return;
    run_inertia(begin_s);
    inertia_.stop();
    now_s_ = begin_s;
    attract_.begin(begin_s, view_);
}

void GestureController::push_tap_action(TapAction action) {
    switch (action) {
        case TapAction::none:
            break;
        case TapAction::next_stone:
            actions_.push_back(GestureAction::next_stone);
            break;
        case TapAction::next_preset:
            actions_.push_back(GestureAction::next_preset);
            break;
    }
}

ViewState GestureController::attract_target() const {
    ViewState target = start_view_;
    target.elevation_deg =
        clamp_between(options_.attract_elevation_deg, min_elevation_deg_, max_elevation_deg_);
    return target;
}

}  // namespace gem::kiosk
