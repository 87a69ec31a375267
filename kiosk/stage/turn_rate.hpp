#pragma once
// How fast the view turns: the angular velocity that carries the last frame's view direction to
// this frame's (their cross product over the time between), from which the stone method
// prepares the views the turn will reach (StoneMethod::prepare: the table decodes them ahead).
// Taken from the views themselves, whatever moves them: a finger, the inertia after a fling,
// attract mode, a replay, the method probe's turn.

#include <glm/glm.hpp>

namespace gem::kiosk {

class TurnRate {
  public:
    // The turn (rad/s) since the direction given last; zero for the first after restart(), or
    // when no time has passed.
    glm::dvec3 next(const glm::dvec3& forward, double now_s) {
        glm::dvec3 omega(0.0);
        if (last_s_ >= 0.0 && now_s > last_s_)
            omega = glm::cross(last_, forward) / (now_s - last_s_);
        last_ = forward;
        last_s_ = now_s;
        return omega;
    }
    void restart() { last_s_ = -1.0; }

  private:
    glm::dvec3 last_{0.0};
    double last_s_ = -1.0;
};

}  // namespace gem::kiosk
