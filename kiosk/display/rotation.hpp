#pragma once
// The picture (what the shopper sees, upright) against the panel's scanout (the mode's pixel
// grid). The panel may sit turned in its casing (the "panel orientation" connector property,
// kernel drm_connector.c) and the kiosk may be mounted turned (DisplayOptions::rotation_deg);
// both add up to one clockwise rotation from the picture to the scanout.

#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>

#include "display/drm_select.hpp"
#include "gpu/pixel_rect.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

// The clockwise turn from the upright picture to the scanout that undoes the panel's mounting.
// "Right Side Up": the panel's right edge is at the top of the casing, so the panel is turned
// a quarter counter-clockwise and the picture must be turned a quarter clockwise (90);
// "Left Side Up" the other way (270); "Upside Down" 180.
int panel_orientation_deg(PanelOrientation orientation);

// (panel + configured) mod 360; an error unless configured is a multiple of 90.
Result<int> total_rotation_deg(PanelOrientation orientation, int configured_deg);

// The picture's size for a scanout of `scanout` pixels: width and height swap at 90 and 270.
glm::ivec2 picture_size_for(glm::ivec2 scanout, int rotation_deg);

// Where each scanout pixel takes its colour from: picture = linear * scanout + offset, both
// in pixels with the origin at the bottom-left corner and y up (GL's window and texture
// coordinates), applied to pixel centres.
struct PictureFromScanout {
    glm::mat2 linear{1.0f};
    glm::vec2 offset{0.0f};
};
PictureFromScanout picture_from_scanout(int rotation_deg, glm::ivec2 picture_size);

// The scanout's pixels that show the picture's pixels in `picture_rect` (both y up).
gpu::PixelRect scanout_rect(const gpu::PixelRect& picture_rect, int rotation_deg,
                            glm::ivec2 picture_size);

}  // namespace gem::kiosk
