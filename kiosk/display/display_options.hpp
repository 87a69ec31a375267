#pragma once
// Display settings from the [display] section of the config (config/gemkiosk.toml).

#include <string>

namespace gem::kiosk {

struct DisplayOptions {
    std::string backend = "drm";  // drm | headless
    // DRM: a card node such as /dev/dri/card0; empty: the first card with a connected output.
    std::string device;
    std::string connector;      // "HDMI-A-1"; empty: the first connected connector
    std::string mode;           // "1920x1080" or "1920x1080@60"; empty: the connector's preferred
    int rotation_deg = 0;       // clockwise, added to the panel's own orientation property
    bool atomic = true;         // atomic modesetting when the driver offers it, else legacy
    int flip_timeout_ms = 250;  // a page flip not completed by then counts as lost
    // Headless: the picture's size and how often a frame is due (0: as fast as it renders).
    int headless_width = 1920;
    int headless_height = 1080;
    double headless_rate_hz = 60.0;
};

}  // namespace gem::kiosk
