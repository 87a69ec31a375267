#include "display/rotation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

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

gpu::PixelRect scanout_rect(const gpu::PixelRect& picture_rect, int rotation_deg,
                            glm::ivec2 picture_size) {
    if (picture_rect.empty()) return {};
    // The map is a quarter turn and a whole-pixel offset, so it takes the rectangle's corners
    // (not only pixel centres) to corners: scanout = linearᵀ (picture − offset).
    const PictureFromScanout map = picture_from_scanout(rotation_deg, picture_size);
    const glm::mat2 back = glm::transpose(map.linear);
    const glm::vec2 a = back * (glm::vec2(picture_rect.x0, picture_rect.y0) - map.offset);
    const glm::vec2 b = back * (glm::vec2(picture_rect.x1, picture_rect.y1) - map.offset);
    const auto side = [](float p, float q) {
        return static_cast<int>(std::lround(std::min(p, q)));
    };
    const auto far = [](float p, float q) { return static_cast<int>(std::lround(std::max(p, q))); };
    return {side(a.x, b.x), side(a.y, b.y), far(a.x, b.x), far(a.y, b.y)};
}

}  // namespace gem::kiosk
