#pragma once
// How the fingers moved between two touch frames, from the fingers present in both (matched
// by contact id). Fingers that arrive or leave between the frames take no part, so adding or
// lifting a finger never makes the view jump: the gesture re-anchors on whoever stays.
//
// With two or more common fingers, the scale and rotation are the least-squares similarity
// between the two point sets about their centroids (the 2-D orthogonal Procrustes problem:
// with a_i, b_i the positions relative to each frame's centroid, the best rotation is
// atan2(sum a_i x b_i, sum a_i . b_i)); for two fingers they reduce to the ratio of the finger
// distances and the turn of the line through them.

#include <vector>

#include <glm/vec2.hpp>

#include "input/input_event.hpp"

namespace gem::kiosk {

struct ContactMotion {
    int common = 0;                  // fingers present in both frames
    glm::dvec2 translation{0.0};     // of their centroid, picture pixels
    double scale = 1.0;              // spread after / spread before; 1 when not measurable
    double rotation_deg = 0.0;       // positive: clockwise as the shopper sees it (y is down)
    bool spread_measurable = false;  // two or more fingers, at least min_spread_px apart
};

// `min_spread_px`: below this mean distance from the centroid (before or after) the fingers
// are too close together for their scale and rotation to mean anything.
ContactMotion contact_motion(const std::vector<Contact>& before, const std::vector<Contact>& after,
                             double min_spread_px);

}  // namespace gem::kiosk
