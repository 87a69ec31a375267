#pragma once
// A fling's spin after the finger lifts: the turning speed decays exponentially,
// v(t) = v0 2^(-t / half_life), so the turn still to come is v(t) tau with
// tau = half_life / ln 2. Each step integrates that exactly, so the path does not depend on the
// frame rate.

#include <glm/vec2.hpp>

namespace gem::kiosk {

class Inertia {
  public:
    // A half-life of zero or less means no inertia.
    void start(glm::dvec2 velocity_deg_per_s, double half_life_s);
    void stop() { active_ = false; }
    // The elevation reached its limit: the spin goes on about the vertical axis only.
    void stop_elevation() { velocity_.y = 0.0; }
    bool active() const { return active_; }
    glm::dvec2 velocity() const { return active_ ? velocity_ : glm::dvec2(0.0); }

    // The turn (azimuth, elevation; degrees) over the next `dt_s` seconds; the speed decays.
    glm::dvec2 advance(double dt_s);

  private:
    bool active_ = false;
    glm::dvec2 velocity_{0.0};
    double tau_s_ = 0.0;
};

}  // namespace gem::kiosk
