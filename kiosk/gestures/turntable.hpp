#pragma once
// One-finger drag turns the ring like a turntable: horizontal motion changes the azimuth (a turn
// about the stone's vertical axis, +y through the table), vertical motion the elevation, and
// the ring stays upright. Why not an arcball: jewellers hold a ring upright and turn it that
// way; the table database covers a band of elevations (docs/design.md, "Tables by view
// direction"), which a turntable keeps to by clamping one number while an arcball would wander
// out of it; and an arcball mixes roll into every drag, whereas here roll belongs to the
// two-finger twist alone, so a shopper can always get back to an upright ring.
//
// Directions, so that the finger pushes the surface it touches (engine/picture/camera.cpp gives
// the basis: towards the eye e = (cos el sin az, sin el, cos el cos az), right = (cos az, 0,
// -sin az), up = right x -e):
//  - the stone's front point p = r e(az0, el0) sits at screen x = p . right(az) =
//    r cos el0 sin(az0 - az) after the camera moves to az: dragging right (+x) must LOWER the
//    azimuth;
//  - at az = az0 its screen height is p . up(el) = r sin(el0 - el): dragging down must RAISE
//    the elevation, the camera climbs and the table tilts toward the viewer, as a finger pushing
//    the front surface down would tilt it.
// With the picture rolled, the drag is first turned back into the unrolled camera's axes, so
// the stone still follows the finger.

#include <glm/vec2.hpp>

namespace gem::kiosk {

// The turn (x: azimuth, y: elevation, degrees) for a drag of `drag_px` picture pixels (x right,
// y down), at `degrees_per_px` and with the view rolled by `roll_deg`.
glm::dvec2 turntable_turn(glm::dvec2 drag_px, double roll_deg, double degrees_per_px);

}  // namespace gem::kiosk
