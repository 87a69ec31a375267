#include "display/rotation.hpp"

#include <cassert>

namespace gem::kiosk {

int panel_orientation_deg(PanelOrientation orientation) {
    switch (orientation) {
        case PanelOrientation::upside_down:
            return 180;
        case PanelOrientation::left_side_up:
            return 270;
        case PanelOrientation::right_side_up:
            return 90;
        case PanelOrientation::normal:
            break;
    }
    return 0;
}

Result<int> total_rotation_deg(PanelOrientation orientation, int configured_deg) {
    if (configured_deg % 90 != 0) {
        return Error{"display rotation " + std::to_string(configured_deg) +
                     ": must be a multiple of 90 degrees (0, 90, 180, 270)"};
    }
    const int total = (panel_orientation_deg(orientation) + configured_deg) % 360;
    return total < 0 ? total + 360 : total;
}

glm::ivec2 picture_size_for(glm::ivec2 scanout, int rotation_deg) {
    assert(rotation_deg % 90 == 0 && rotation_deg >= 0 && rotation_deg < 360);
    return rotation_deg % 180 == 0 ? scanout : glm::ivec2(scanout.y, scanout.x);
}

PictureFromScanout picture_from_scanout(int rotation_deg, glm::ivec2 picture_size) {
    // Derived with y down first (picture pixel (x, y) lands on scanout (h - y, x) for a
    // clockwise quarter turn), then both flipped to y up. glm matrices are column-major:
    // mat2(a, b, c, d) has columns (a, b) and (c, d).
    const float w = static_cast<float>(picture_size.x);
    const float h = static_cast<float>(picture_size.y);
    PictureFromScanout map;
    switch (rotation_deg) {
        case 90:  // picture x = w - Y, picture y = X
            map.linear = glm::mat2(0.0f, 1.0f, -1.0f, 0.0f);
            map.offset = {w, 0.0f};
            break;
        case 180:  // picture x = w - X, picture y = h - Y
            map.linear = glm::mat2(-1.0f, 0.0f, 0.0f, -1.0f);
            map.offset = {w, h};
            break;
        case 270:  // picture x = Y, picture y = h - X
            map.linear = glm::mat2(0.0f, -1.0f, 1.0f, 0.0f);
            map.offset = {0.0f, h};
            break;
        default:
            assert(rotation_deg == 0);
            break;
    }
    return map;
}

}  // namespace gem::kiosk
