#pragma once
// Attract mode: while nobody touches the kiosk, the ring turns slowly about its vertical axis,
// the view eases to a pleasant elevation (and roll and zoom back to the start view), and the
// kiosk cycles presets and stones. Everything is a function of the time since attract mode
// began, so the view does not depend on the frame rate. The ease is a smoothstep
// (3u^2 - 2u^3), so neither the view nor its speed jumps where attract mode takes over from
// the shopper's view; zoom eases geometrically, as zoom steps are ratios.

#include <vector>

#include "gestures/gesture_options.hpp"
#include "gestures/gesture_output.hpp"

namespace gem::kiosk {

class AttractMode {
  public:
    explicit AttractMode(const GestureOptions& options) : options_(options) {}

    bool active() const { return active_; }
    // Starts at `time_s` from `view` (where the shopper left it).
    void begin(double time_s, const ViewState& view);
    void end() { active_ = false; }
    // The view was set from outside (a new stone): ease on from there; the actions keep time.
    void restart_ease(double time_s, const ViewState& view);

    // The view at `now_s` (not before the last call), easing toward `target`'s elevation, roll
    // and zoom; appends the actions due since the last call (each kind at most once a call, so
    // a stalled main loop catching up does not skip through the catalogue).
    ViewState advance(double now_s, const ViewState& target, std::vector<GestureAction>& actions);

  private:
    GestureOptions options_;
    bool active_ = false;
    double ease_start_s_ = 0.0;
    ViewState ease_start_view_;
    double next_preset_s_ = 0.0;
    double next_stone_s_ = 0.0;
};

}  // namespace gem::kiosk
