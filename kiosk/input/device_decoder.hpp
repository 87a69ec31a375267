#pragma once
// The one path from a device's raw events to the kiosk's InputEvents, shared by real devices
// (evdev_device) and recordings (evemu_replay) so that a replay behaves as the device would:
// touchscreens and absolute pointers through TouchTracker and TouchMapping, pointers through
// PointerTracker, keyboards and anything else dropped.

#include <linux/input.h>

#include <functional>
#include <optional>
#include <vector>

#include "input/device_kind.hpp"
#include "input/input_event.hpp"
#include "input/pointer_tracker.hpp"
#include "input/touch_mapping.hpp"
#include "input/touch_tracker.hpp"

namespace gem::kiosk {

class DeviceDecoder {
  public:
    DeviceDecoder(DeviceKind kind, const TouchAxes& axes);

    // Appends what the event completed. When it ends a SYN_DROPPED discard, asks snapshot for
    // the device's current state and resynchronises from it.
    void feed(const input_event& event, const TouchMapping& mapping,
              const std::function<TouchSnapshot()>& snapshot, std::vector<InputEvent>& out);
    // Resynchronises now (libevdev reports SYN_DROPPED after it has synced its own state).
    void resynchronise(const TouchSnapshot& snapshot, double time_s, const TouchMapping& mapping,
                       std::vector<InputEvent>& out);

    DeviceKind kind() const { return kind_; }

  private:
    void emit_touch_frame(double time_s, const TouchMapping& mapping,
                          std::vector<InputEvent>& out) const;

    DeviceKind kind_;
    std::optional<TouchTracker> touch_;
    PointerTracker pointer_;
};

}  // namespace gem::kiosk
