#include "gestures/inertia.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace gem::kiosk {

namespace {

// Below this much turn still to come the spin is invisible; stop it so the view settles.
constexpr double kSettledDeg = 1e-3;

}  // namespace

void Inertia::start(glm::dvec2 velocity_deg_per_s, double half_life_s) {
    active_ = half_life_s > 0.0;
    velocity_ = velocity_deg_per_s;
    tau_s_ = half_life_s / std::numbers::ln2;
}

glm::dvec2 Inertia::advance(double dt_s) {
    if (!active_ || dt_s <= 0.0) return glm::dvec2(0.0);
    const double remaining = std::exp(-dt_s / tau_s_);
    const glm::dvec2 turn = velocity_ * tau_s_ * (1.0 - remaining);
    velocity_ *= remaining;
    if (glm::length(velocity_) * tau_s_ < kSettledDeg) active_ = false;
    return turn;
}

}  // namespace gem::kiosk
