#pragma once
// The view a kiosk opens with, and that attract mode eases roll and zoom back to: the ring
// seen from a little to the side and above, as a shopper across the counter sees it. Zoom 1
// fits the whole ring's sphere about the stone's centre, where the stone is a small part of
// the picture; 1.6 gives the stone about a fifth of the picture's height and lets the bottom
// of the shank leave the frame.

#include "gestures/gesture_output.hpp"

namespace gem::kiosk {

inline constexpr ViewState kStartView{
    .azimuth_deg = 20.0, .elevation_deg = 40.0, .roll_deg = 0.0, .zoom = 1.6};

}  // namespace gem::kiosk
