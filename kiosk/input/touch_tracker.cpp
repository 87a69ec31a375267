#include "input/touch_tracker.hpp"

#include <algorithm>
#include <cassert>

namespace gem::kiosk {

TouchTracker::TouchTracker(const TouchAxes& axes) : axes_(axes) {
    assert(axes.slot_count >= 1);
    slots_.resize(static_cast<std::size_t>(axes.slot_count));
}

FeedResult TouchTracker::feed(const input_event& event) {
    if (event.type == EV_SYN && event.code == SYN_DROPPED) {
        // event-codes.rst: "Client should ignore all events up to and including next SYN_REPORT
        // event and query the device (using EVIOCG* ioctls) to obtain its current state."
        discarding_ = true;
        frame_contacts_.clear();
        pending_ = {};
        return FeedResult::none;
    }
    if (discarding_) {
        if (event.type == EV_SYN && event.code == SYN_REPORT) return FeedResult::resync_needed;
        return FeedResult::none;
    }
    switch (event.type) {
        case EV_ABS:
            feed_abs(event);
            return FeedResult::none;
        case EV_KEY:
            if (event.code == axes_.contact_key) touching_ = event.value != 0;
            return FeedResult::none;
        case EV_SYN:
            if (event.code == SYN_MT_REPORT && axes_.protocol == TouchProtocol::multitouch_a) {
                // An empty SYN_MT_REPORT is how some protocol A drivers say "no contact".
                if (pending_.has_position) frame_contacts_.push_back(pending_);
                pending_ = {};
                return FeedResult::none;
            }
            if (event.code == SYN_REPORT) {
                end_frame();
                return FeedResult::frame;
            }
            return FeedResult::none;
        default:
            return FeedResult::none;
    }
}

void TouchTracker::feed_abs(const input_event& event) {
    switch (axes_.protocol) {
        case TouchProtocol::multitouch_b: {
            if (event.code == ABS_MT_SLOT) {
                current_slot_ = event.value;
                return;
            }
            // The kernel never sends a slot outside ABS_MT_SLOT's range; a recording might.
            if (current_slot_ < 0 || current_slot_ >= axes_.slot_count) return;
            TouchSlotState& slot = slots_[static_cast<std::size_t>(current_slot_)];
            if (event.code == ABS_MT_TRACKING_ID) slot.tracking_id = event.value;
            if (event.code == ABS_MT_POSITION_X) slot.x = event.value;
            if (event.code == ABS_MT_POSITION_Y) slot.y = event.value;
            return;
        }
        case TouchProtocol::multitouch_a:
            if (event.code == ABS_MT_TRACKING_ID) pending_.tracking_id = event.value;
            if (event.code == ABS_MT_POSITION_X || event.code == ABS_MT_POSITION_Y) {
                if (!pending_.has_position) {
                    // Start from the same contact of the previous frame, so that an axis a
                    // driver leaves out keeps its value.
                    const std::size_t index = frame_contacts_.size();
                    if (index < previous_raw_.size()) {
                        pending_.x = previous_raw_[index].x;
                        pending_.y = previous_raw_[index].y;
                    }
                    pending_.has_position = true;
                }
                if (event.code == ABS_MT_POSITION_X) pending_.x = event.value;
                if (event.code == ABS_MT_POSITION_Y) pending_.y = event.value;
            }
            return;
        case TouchProtocol::single_touch:
            if (event.code == ABS_X) x_ = event.value;
            if (event.code == ABS_Y) y_ = event.value;
            return;
    }
}

void TouchTracker::end_frame() {
    contacts_.clear();
    switch (axes_.protocol) {
        case TouchProtocol::multitouch_b:
            for (const TouchSlotState& slot : slots_) {
                if (slot.tracking_id >= 0)
                    contacts_.push_back({slot.tracking_id, normalise(slot.x, slot.y)});
            }
            return;
        case TouchProtocol::multitouch_a:
            // A contact whose SYN_MT_REPORT never came still counts.
            if (pending_.has_position) frame_contacts_.push_back(pending_);
            pending_ = {};
            previous_raw_.clear();
            for (std::size_t i = 0; i < frame_contacts_.size(); ++i) {
                const PendingContact& contact = frame_contacts_[i];
                const int id = contact.tracking_id >= 0 ? contact.tracking_id : static_cast<int>(i);
                contacts_.push_back({id, normalise(contact.x, contact.y)});
                previous_raw_.push_back({id, contact.x, contact.y});
            }
            frame_contacts_.clear();
            return;
        case TouchProtocol::single_touch:
            if (touching_) contacts_.push_back({0, normalise(x_, y_)});
            return;
    }
}

void TouchTracker::resynchronise(const TouchSnapshot& snapshot) {
    discarding_ = false;
    frame_contacts_.clear();
    pending_ = {};
    x_ = snapshot.x;
    y_ = snapshot.y;
    touching_ = axes_.contact_key == BTN_LEFT ? snapshot.left_button : snapshot.touching;
    switch (axes_.protocol) {
        case TouchProtocol::multitouch_b:
            std::fill(slots_.begin(), slots_.end(), TouchSlotState{});
            std::copy_n(snapshot.slots.begin(), std::min(snapshot.slots.size(), slots_.size()),
                        slots_.begin());
            current_slot_ = snapshot.current_slot;
            end_frame();
            return;
        case TouchProtocol::multitouch_a:
            // The kernel keeps no per-contact state for protocol A; every frame repeats all
            // contacts, so the next frame is complete. Until then only a lift is known.
            if (!snapshot.touching) {
                contacts_.clear();
                previous_raw_.clear();
            }
            return;
        case TouchProtocol::single_touch:
            end_frame();
            return;
    }
}

glm::dvec2 TouchTracker::normalise(int x, int y) const {
    const auto along = [](int value, const AxisRange& range) {
        if (range.maximum <= range.minimum) return 0.0;
        const double t = static_cast<double>(value - range.minimum) /
                         static_cast<double>(range.maximum - range.minimum);
        return std::clamp(t, 0.0, 1.0);
    };
    return {along(x, axes_.x), along(y, axes_.y)};
}

}  // namespace gem::kiosk
