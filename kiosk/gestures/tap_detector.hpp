#pragma once
// Tells a tap from the other things fingers do, over one touch sequence (from the first finger
// down to the last one up). A tap is short (tap_max_s from first down to last up) and no finger
// strays more than tap_max_move_px from where it came down, so a drag is never a tap. One
// finger is a tap; two fingers that were down together, and no third, are a two-finger tap.

#include <vector>

#include <glm/vec2.hpp>

#include "input/input_event.hpp"

namespace gem::kiosk {

enum class TapKind { none, one_finger, two_finger };

class TapDetector {
  public:
    TapDetector(double max_s, double max_move_px);

    void begin(double time_s);  // the first finger came down
    void update(const TouchFrame& frame);
    void disqualify() { qualifies_ = false; }  // e.g. this touch woke the kiosk from attract mode
    TapKind end(double time_s);                // the last finger lifted

  private:
    struct Finger {
        int id = 0;
        glm::dvec2 down_position{0.0};
    };
    double max_s_;
    double max_move_px_;
    double begin_s_ = 0.0;
    bool qualifies_ = false;
    std::size_t most_at_once_ = 0;
    std::vector<Finger> fingers_;  // every finger of the sequence
};

}  // namespace gem::kiosk
