#include "gestures/tap_detector.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace gem::kiosk {

TapDetector::TapDetector(double max_s, double max_move_px)
    : max_s_(max_s), max_move_px_(max_move_px) {}

void TapDetector::begin(double time_s) {
    begin_s_ = time_s;
    qualifies_ = true;
    most_at_once_ = 0;
    fingers_.clear();
}

void TapDetector::update(const TouchFrame& frame) {
    if (!qualifies_) return;
    most_at_once_ = std::max(most_at_once_, frame.contacts.size());
    for (const Contact& c : frame.contacts) {
        auto known = std::find_if(fingers_.begin(), fingers_.end(),
                                  [&](const Finger& f) { return f.id == c.id; });
        if (known == fingers_.end()) {
            fingers_.push_back({c.id, c.position});
        } else if (glm::distance(c.position, known->down_position) > max_move_px_) {
            qualifies_ = false;
        }
    }
    if (fingers_.size() > 2) qualifies_ = false;
}

TapKind TapDetector::end(double time_s) {
    const bool tap = qualifies_ && time_s - begin_s_ <= max_s_;
    qualifies_ = false;
    if (!tap) return TapKind::none;
    if (fingers_.size() == 1) return TapKind::one_finger;
    if (fingers_.size() == 2 && most_at_once_ == 2) return TapKind::two_finger;
    return TapKind::none;
}

}  // namespace gem::kiosk
