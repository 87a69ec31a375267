#include "gestures/contact_motion.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace gem::kiosk {

namespace {

const Contact* find_contact(const std::vector<Contact>& contacts, int id) {
    for (const Contact& c : contacts) {
        if (c.id == id) return &c;
    }
    return nullptr;
}

}  // namespace

ContactMotion contact_motion(const std::vector<Contact>& before, const std::vector<Contact>& after,
                             double min_spread_px) {
    ContactMotion motion;
    glm::dvec2 centre_before{0.0};
    glm::dvec2 centre_after{0.0};
    for (const Contact& b : before) {
        if (const Contact* a = find_contact(after, b.id)) {
            ++motion.common;
            centre_before += b.position;
            centre_after += a->position;
        }
    }
    if (motion.common == 0) return motion;
    centre_before /= static_cast<double>(motion.common);
    centre_after /= static_cast<double>(motion.common);
    motion.translation = centre_after - centre_before;
    if (motion.common < 2) return motion;

    double spread_before = 0.0;
    double spread_after = 0.0;
    double sum_cross = 0.0;
    double sum_dot = 0.0;
    for (const Contact& b : before) {
        const Contact* a = find_contact(after, b.id);
        if (a == nullptr) continue;
        const glm::dvec2 u = b.position - centre_before;
        const glm::dvec2 v = a->position - centre_after;
        spread_before += glm::length(u);
        spread_after += glm::length(v);
        sum_cross += u.x * v.y - u.y * v.x;
        sum_dot += glm::dot(u, v);
    }
    const double n = static_cast<double>(motion.common);
    if (spread_before / n < min_spread_px || spread_after / n < min_spread_px) return motion;
    motion.spread_measurable = true;
    motion.scale = spread_after / spread_before;
    // In picture coordinates (y down) a positive cross product is a clockwise turn on screen.
    motion.rotation_deg = std::atan2(sum_cross, sum_dot) * 180.0 / std::numbers::pi;
    return motion;
}

}  // namespace gem::kiosk
