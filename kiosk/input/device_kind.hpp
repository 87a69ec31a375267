#pragma once
// What an input device is to the kiosk, from what it declares it can report
// (Documentation/input/event-codes.rst, "Device properties" and "Guidelines"): a touchscreen
// (INPUT_PROP_DIRECT, or absolute positions with BTN_TOUCH), an absolute pointer (absolute
// positions with a left button and no touch: a touch controller in "mouse mode", a virtual
// machine's tablet), a pointer (relative motion with a left button), a keyboard (typing keys) or
// something the kiosk ignores.

#include <string_view>

#include "input/touch_tracker.hpp"

namespace gem::kiosk {

enum class DeviceKind { touchscreen, absolute_pointer, pointer, keyboard, other };

struct DeviceCapabilities {
    bool direct = false;       // INPUT_PROP_DIRECT
    bool mt_position = false;  // ABS_MT_POSITION_X and _Y
    bool mt_slot = false;      // ABS_MT_SLOT: protocol B
    bool abs_xy = false;       // ABS_X and ABS_Y
    bool btn_touch = false;
    bool rel_xy = false;  // REL_X and REL_Y
    bool btn_left = false;
    bool typing_keys = false;  // KEY_A and KEY_ENTER: a keyboard, not a power button
    AxisRange mt_x, mt_y, abs_x, abs_y;
    int slot_maximum = 0;
};

DeviceKind classify(const DeviceCapabilities& capabilities);
std::string_view to_string(DeviceKind kind);

// How a touchscreen or an absolute pointer reports and on which ranges (protocol B over A over
// single touch; an absolute pointer is single touch with BTN_LEFT as its contact).
TouchAxes touch_axes(const DeviceCapabilities& capabilities);

}  // namespace gem::kiosk
