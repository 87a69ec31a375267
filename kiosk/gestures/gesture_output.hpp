#pragma once
// What the gestures hand to the rest of the kiosk: the view the renderer draws, and discrete
// actions (a tap, or attract mode's slide show) for the main loop to carry out.

#include <cmath>

namespace gem::kiosk {

// The same four numbers, with the same meaning, as gem::CameraSettings
// (engine/picture/camera.hpp): azimuth about +y measured from +z toward +x; elevation above the
// girdle plane; roll turns the camera counter-clockwise about its view axis (so the picture
// turns clockwise); zoom 1 fits the stone's bounding sphere to the shorter picture side. The
// gestures keep azimuth and roll in [-180, 180) and elevation inside the stone's database band.
struct ViewState {
    double azimuth_deg = 0.0;
    double elevation_deg = 90.0;
    double roll_deg = 0.0;
    double zoom = 1.0;
};

enum class GestureAction { next_stone, next_preset };

// `degrees` folded into [-180, 180).
inline double wrap_degrees(double degrees) {
    return degrees - 360.0 * std::floor((degrees + 180.0) / 360.0);
}

// The signed turn in (-180, 180] that takes `from` to `to` the short way round.
inline double angle_difference_deg(double to, double from) {
    const double d = wrap_degrees(to - from);
    return d == -180.0 ? 180.0 : d;
}

}  // namespace gem::kiosk
