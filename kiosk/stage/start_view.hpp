#pragma once
// The view a kiosk opens with, and that attract mode eases roll and zoom back to: the ring in
// three-quarter view from above, as jewellery is photographed (the band's opening seen at an
// angle, the stone on top, toward the viewer). Zoom is
// relative to the start view's framing (framing.hpp): 1 shows the stone as the hero with the
// whole ring in the picture.

#include "gestures/gesture_output.hpp"

namespace gem::kiosk {

inline constexpr ViewState kStartView{
    .azimuth_deg = 65.0, .elevation_deg = 40.0, .roll_deg = 0.0, .zoom = 1.0};

}  // namespace gem::kiosk
