#pragma once
// Turns the shopper's fingers into the view the renderer draws (docs/design.md, "Data flow":
// touch -> gestures -> camera). Pure logic: no I/O and no clock; time comes from the events and
// from advance(), both CLOCK_MONOTONIC seconds (kiosk/input/input_event.hpp).
//  - one finger drags the ring round like a turntable (gestures/turntable.hpp), and a fling
//    keeps it spinning, slowing with GestureOptions::inertia_half_life_s; a touch stops it;
//  - two or more fingers pinch to zoom and twist to roll; fingers arriving or leaving
//    mid-gesture re-anchor it, so the view never jumps (gestures/contact_motion.hpp); moving
//    both fingers together does nothing (the camera orbits the stone's centre: nothing to pan);
//  - the wheel zooms by wheel_zoom_step a notch (about the centre, like a pinch);
//  - a tap and a two-finger tap give the configured actions (gestures/tap_detector.hpp);
//  - after idle_s without any input event, attract mode (gestures/attract_mode.hpp); the
//    first input ends it, and the gesture goes on from the view of that moment. Idleness counts
//    events, not fingers down, so a stuck contact on a dirty panel cannot keep the kiosk out of
//    attract mode; when such a finger moves again it counts as a new touch.
//
// Use: on_event() for every input event, advance(now) once a frame before reading view(), and
// take_actions() for the taps and attract mode's slide show.

#include <vector>

#include <glm/vec2.hpp>

#include "gestures/attract_mode.hpp"
#include "gestures/fling_estimator.hpp"
#include "gestures/gesture_options.hpp"
#include "gestures/gesture_output.hpp"
#include "gestures/inertia.hpp"
#include "gestures/tap_detector.hpp"
#include "input/input_event.hpp"

namespace gem::kiosk {

class GestureController {
  public:
    // `start_view`: the view shown first; attract mode eases roll and zoom back to it.
    // `options` come validated from the config (positive zoom limits, min_zoom <= max_zoom).
    GestureController(const GestureOptions& options, const ViewState& start_view);

    // The picture's size in pixels (drag gain: degrees_per_picture_height per picture height).
    // Until it is set, drags do not turn the ring.
    void set_picture_size(glm::dvec2 size_px);
    // The band of elevations the stone's database covers (precondition: min <= max); the view
    // is kept inside it, and a view outside it now is moved in.
    void set_elevation_limits(double min_deg, double max_deg);

    void on_event(const InputEvent& event);
    // Moves inertia and attract mode on to `now_s`; a time earlier than one already seen is
    // ignored. The first call (or event) starts the idle clock.
    void advance(double now_s);

    const ViewState& view() const { return view_; }
    // The actions since the last call, oldest first.
    std::vector<GestureAction> take_actions();
    bool attract_mode() const { return attract_.active(); }
    // Shows `view` (clamped to the limits) at once and stops any spin; a gesture in progress
    // goes on from it, and attract mode eases on from it.
    void reset_view(const ViewState& view);

  private:
    void on_touch_frame(const TouchFrame& frame);
    void on_wheel(const WheelStep& wheel);
    void move_contacts(const std::vector<Contact>& before, const TouchFrame& after, bool anchor);
    void touch_up(double time_s);
    void turn(glm::dvec2 turn_deg);  // azimuth, elevation
    void scale_zoom(double factor);
    void run_inertia(double until_s);
    void enter_attract_if_idle(double now_s);
    void push_tap_action(TapAction action);
    ViewState attract_target() const;

    GestureOptions options_;
    ViewState start_view_;
    ViewState view_;
    glm::dvec2 picture_size_{0.0};
    double min_elevation_deg_ = -90.0;
    double max_elevation_deg_ = 90.0;

    bool clock_started_ = false;
    double now_s_ = 0.0;
    double last_input_s_ = 0.0;

    std::vector<Contact> contacts_;  // fingers down after the last touch frame
    glm::dvec2 drag_turn_deg_{0.0};  // every one-finger turn so far, unclamped (for the fling)
    FlingEstimator fling_;
    Inertia inertia_;
    TapDetector tap_;
    AttractMode attract_;
    std::vector<GestureAction> actions_;
};

}  // namespace gem::kiosk
