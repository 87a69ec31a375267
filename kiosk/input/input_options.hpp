#pragma once
// Input settings from the [input] section of the kiosk's config (config/gemkiosk.toml).

#include <array>
#include <string>
#include <vector>

namespace gem::kiosk {

struct InputOptions {
    std::string device_dir = "/dev/input";  // watched for event* nodes coming and going
    std::vector<std::string> devices;       // empty: every touchscreen, pointer and keyboard
    // libinput's calibration matrix convention (LIBINPUT_CALIBRATION_MATRIX in udev): applied
    // to coordinates normalised to [0, 1] on the device's axes, x' = a x + b y + c,
    // y' = d x + e y + f; identity by default.
    std::array<double, 6> calibration{1.0, 0.0, 0.0, 0.0, 1.0, 0.0};
    // Touch rotation relative to the picture, clockwise degrees (0, 90, 180, 270); by default
    // it follows the display's rotation (the panel and its touch layer turn together).
    int rotation_deg = -1;  // -1: the display's
};

}  // namespace gem::kiosk
