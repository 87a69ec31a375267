#pragma once
// Decodes the raw evdev events of ONE touch device into the complete list of fingers down after
// every frame (SYN_REPORT), in coordinates normalised to [0, 1] of the device's axis ranges.
// Three kinds of device (Documentation/input/multi-touch-protocol.rst in the kernel tree):
//  - protocol B: ABS_MT_SLOT selects a slot, ABS_MT_TRACKING_ID >= 0 starts a contact in it,
//    -1 ends it; only changes are sent, so each slot keeps its last values;
//  - protocol A: every frame repeats every contact, each closed by SYN_MT_REPORT; a frame with
//    no contact (or only empty SYN_MT_REPORTs) means every finger lifted;
//  - single touch: ABS_X / ABS_Y with BTN_TOUCH (or BTN_LEFT: an absolute pointer).
// SYN_DROPPED (Documentation/input/event-codes.rst): the client must ignore everything up to and
// including the next SYN_REPORT, then query the device's state; feed() says when, and
// resynchronise() takes that state (libevdev's for a device, the replay's kept state for a
// recording).

#include <linux/input.h>

#include <vector>

#include <glm/vec2.hpp>

namespace gem::kiosk {

enum class TouchProtocol { multitouch_b, multitouch_a, single_touch };

struct AxisRange {
    int minimum = 0;
    int maximum = 0;
};

// What the decoder needs to know about a device: how it reports and the ranges of the axes it
// reports positions on (ABS_MT_POSITION_X/Y for multitouch, ABS_X/Y for single touch).
struct TouchAxes {
    TouchProtocol protocol = TouchProtocol::multitouch_b;
    AxisRange x;
    AxisRange y;
    int slot_count = 1;  // protocol B: ABS_MT_SLOT's maximum + 1
    // The key that is down while touching: BTN_TOUCH, or BTN_LEFT for an absolute pointer.
    int contact_key = BTN_TOUCH;
};

// The device's state as the kernel holds it, for resynchronising after SYN_DROPPED.
struct TouchSlotState {
    int tracking_id = -1;  // -1: no contact in this slot
    int x = 0;
    int y = 0;
};
struct TouchSnapshot {
    std::vector<TouchSlotState> slots;  // protocol B
    int current_slot = 0;               // the slot that later ABS_MT_* events go to
    int x = 0;                          // ABS_X / ABS_Y and BTN_TOUCH (single touch, protocol A)
    int y = 0;
    bool touching = false;
    bool left_button = false;  // BTN_LEFT, for pointers
};

struct NormalisedContact {
    int id = 0;  // tracking id (protocol B, protocol A when sent), else the order in the frame
    glm::dvec2 position{0.0};  // [0, 1] on the device's axes
};

enum class FeedResult {
    none,           // nothing new yet
    frame,          // a SYN_REPORT completed a frame: contacts() is the new full list
    resync_needed,  // a SYN_DROPPED ended: call resynchronise() with the device's current state
};

class TouchTracker {
  public:
    explicit TouchTracker(const TouchAxes& axes);

    FeedResult feed(const input_event& event);
    // Rebuilds the contacts from the device's state (and ends any SYN_DROPPED discarding):
    // fingers lifted meanwhile are gone, new ones present, moved ones at their new positions.
    void resynchronise(const TouchSnapshot& snapshot);

    const std::vector<NormalisedContact>& contacts() const { return contacts_; }
    const TouchAxes& axes() const { return axes_; }

  private:
    struct PendingContact {
        int tracking_id = -1;
        int x = 0;
        int y = 0;
        bool has_position = false;
    };

    void feed_abs(const input_event& event);
    void end_frame();
    glm::dvec2 normalise(int x, int y) const;

    TouchAxes axes_;
    bool discarding_ = false;  // after SYN_DROPPED, until the next SYN_REPORT
    // Protocol B: the slots as the events have set them.
    std::vector<TouchSlotState> slots_;
    int current_slot_ = 0;
    // Protocol A: the contacts of the frame being received and the one being filled.
    std::vector<PendingContact> frame_contacts_;
    PendingContact pending_;
    std::vector<TouchSlotState> previous_raw_;  // the last frame's contacts, unnormalised
    // Single touch.
    int x_ = 0;
    int y_ = 0;
    bool touching_ = false;

    std::vector<NormalisedContact> contacts_;
};

}  // namespace gem::kiosk
