#pragma once
// How the start view frames a ring, as a jewellery photograph does: the stone is the hero and
// the whole ring is in the picture. The rule, at the start view's angles (orthographic):
//  - the girdle's width on screen is at least `stone_share` of the picture's height;
//  - the stone and ring fit inside the picture with a margin of kFramingMargin per side,
//    centred on their outline's middle (so a solitaire sits above the middle, its shank
//    below it);
//  - within those two, the picture is as tight as it can be (the stone as large as fits).
// When both cannot hold (a stone tiny in a wide ring), the stone's share wins, the ring is cut
// off where it must be, and `ring_cut` says so. The shift moves the picture, not the view, so
// a turn still turns about the stone's centre.

#include <vector>

#include <glm/glm.hpp>

#include "gestures/gesture_output.hpp"
#include "picture/camera.hpp"

namespace gem::kiosk {

inline constexpr double kFramingMargin = 0.04;  // of the picture's width or height, per side

struct Framing {
    double zoom = 1.0;         // Camera zoom (CameraSettings::zoom) at view zoom 1
    glm::dvec2 shift{0.0};     // Camera shift (CameraSettings::shift)
    double stone_share = 0.0;  // the girdle's width / the picture's height, as framed
    bool ring_cut = false;
};

// `stone` and `ring`: vertices in the stone frame (mm); `scene_radius_mm` the radius Camera
// zoom 1 fits (FrameRenderer::scene_radius_mm).
Framing frame_ring(const std::vector<glm::dvec3>& stone, const std::vector<glm::dvec3>& ring,
                   const ViewState& start, glm::ivec2 picture, double scene_radius_mm,
                   double stone_share);

// The camera for `view` in a picture framed by `framing`: view.zoom scales the framed zoom.
CameraSettings framed_camera(const ViewState& view, const Framing& framing);

}  // namespace gem::kiosk
