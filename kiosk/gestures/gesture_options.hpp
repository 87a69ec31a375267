#pragma once
// Gesture and attract-mode settings from the [gestures] and [attract] sections of the config.

#include <string>

namespace gem::kiosk {

enum class TapAction { none, next_stone, next_preset };

struct GestureOptions {
    double degrees_per_picture_height = 180.0;  // a drag across the picture's height turns this
    double inertia_half_life_s = 0.35;          // a fling's spin halves in this time
    double min_zoom = 0.6;
    double max_zoom = 3.0;
    double wheel_zoom_step = 1.1;  // zoom factor per wheel notch
    TapAction tap = TapAction::next_stone;
    TapAction two_finger_tap = TapAction::next_preset;
    double tap_max_s = 0.25;          // a touch longer than this is not a tap
    double tap_max_move_px = 12.0;    // nor one that moved further
    double idle_s = 60.0;             // attract mode after this long without a touch; 0: never
    double attract_deg_per_s = 12.0;  // the ring's slow turn in attract mode
    double attract_preset_s = 20.0;   // attract mode cycles presets this often
    double attract_stone_s = 60.0;    // and stones this often
    // Added by the gestures module (defaults chosen there; the config may leave them out):
    double attract_elevation_deg = 30.0;  // attract mode eases the view to this elevation,
    double attract_ease_s = 4.0;          // over this long (and roll and zoom back to the start)
    double fling_window_s = 0.08;         // a fling's speed is measured over this much drag
    double fling_min_deg_per_s = 15.0;    // slower than this on lifting: no inertia
    double fling_max_deg_per_s = 720.0;   // a fling never spins faster than this
};

}  // namespace gem::kiosk
