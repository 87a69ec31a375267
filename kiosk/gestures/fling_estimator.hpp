#pragma once
// The turning speed at the moment a finger lifts, from the drag's recent history. Touch
// positions are noisy and arrive irregularly, so the speed is not the last step between two
// frames but the least-squares slope of the turn against time over the last `window_s`.
// A panel sends nothing while a finger rests (the kernel drops unchanged values and then the
// empty frame), and the lift comes in the report after the last position: so the window ends
// one report interval (the last spacing between samples) before the lift, and any longer wait
// counts as the finger resting at its last position. The window starts at the position
// interpolated there. A drag that stopped well before the lift thus gives a speed of zero, one
// that stopped just before it a proportionally smaller one.

#include <vector>

#include <glm/vec2.hpp>

namespace gem::kiosk {

class FlingEstimator {
  public:
    explicit FlingEstimator(double window_s);

    // Starts a new history (a finger came down, or the drag re-anchored) at `turn_deg`.
    void restart(double time_s, glm::dvec2 turn_deg);
    // The accumulated turn (azimuth, elevation; degrees, unclamped) after a frame at time_s.
    void add(double time_s, glm::dvec2 turn_deg);
    // Degrees per second for a lift at `lift_time_s`; zero without a history.
    glm::dvec2 velocity(double lift_time_s) const;

  private:
    struct Sample {
        double time_s = 0.0;
        glm::dvec2 turn_deg{0.0};
    };
    double window_s_;
    std::vector<Sample> samples_;  // oldest first; the first may lie before the window
};

}  // namespace gem::kiosk
