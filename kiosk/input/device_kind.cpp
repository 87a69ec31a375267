#include "input/device_kind.hpp"

#include <algorithm>

namespace gem::kiosk {

DeviceKind classify(const DeviceCapabilities& c) {
    const bool absolute = c.mt_position || c.abs_xy;
    if (absolute && (c.direct || c.btn_touch)) return DeviceKind::touchscreen;
    // Absolute axes and a mouse button but neither INPUT_PROP_DIRECT nor BTN_TOUCH: udev's
    // input_id builtin (test_pointers()) calls such a device a mouse, as virtual machines' USB
    // tablets are. Its positions cover the screen as a touchscreen's do; the button is the
    // finger.
    if (c.abs_xy && c.btn_left && !c.rel_xy) return DeviceKind::absolute_pointer;
    if (c.rel_xy && c.btn_left) return DeviceKind::pointer;
    if (c.typing_keys) return DeviceKind::keyboard;
    return DeviceKind::other;
}

std::string_view to_string(DeviceKind kind) {
    switch (kind) {
        case DeviceKind::touchscreen:
            return "touchscreen";
        case DeviceKind::absolute_pointer:
            return "absolute pointer";
        case DeviceKind::pointer:
            return "pointer";
        case DeviceKind::keyboard:
            return "keyboard";
        case DeviceKind::other:
            break;
    }
    return "other";
}

TouchAxes touch_axes(const DeviceCapabilities& c) {
    TouchAxes axes;
    if (c.mt_position) {
        axes.protocol = c.mt_slot ? TouchProtocol::multitouch_b : TouchProtocol::multitouch_a;
        axes.x = c.mt_x;
        axes.y = c.mt_y;
        axes.slot_count = c.mt_slot ? std::max(1, c.slot_maximum + 1) : 1;
    } else {
        axes.protocol = TouchProtocol::single_touch;
        axes.x = c.abs_x;
        axes.y = c.abs_y;
        // Absolute pointers have no BTN_TOUCH: their left button is the finger.
        if (!c.btn_touch && c.btn_left) axes.contact_key = BTN_LEFT;
    }
    return axes;
}

}  // namespace gem::kiosk
