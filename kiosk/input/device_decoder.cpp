#include "input/device_decoder.hpp"

namespace gem::kiosk {

DeviceDecoder::DeviceDecoder(DeviceKind kind, const TouchAxes& axes)
    : kind_(kind), pointer_(glm::dvec2(1.0)) {
    if (kind == DeviceKind::touchscreen || kind == DeviceKind::absolute_pointer)
        touch_.emplace(axes);
}

void DeviceDecoder::feed(const input_event& event, const TouchMapping& mapping,
                         const std::function<TouchSnapshot()>& snapshot,
                         std::vector<InputEvent>& out) {
    switch (kind_) {
        case DeviceKind::touchscreen:
        case DeviceKind::absolute_pointer:
            switch (touch_->feed(event)) {
                case FeedResult::none:
                    return;
                case FeedResult::frame:
                    emit_touch_frame(event_time_s(event), mapping, out);
                    return;
                case FeedResult::resync_needed:
                    resynchronise(snapshot(), event_time_s(event), mapping, out);
                    return;
            }
            return;
        case DeviceKind::pointer:
            if (pointer_.feed(event, mapping.picture_size(), out))
                pointer_.resynchronise(snapshot().left_button, event_time_s(event), out);
            return;
        case DeviceKind::keyboard:
        case DeviceKind::other:
            // Nothing a shopper types may reach anything: keys are read and dropped.
            return;
    }
}

void DeviceDecoder::resynchronise(const TouchSnapshot& snapshot, double time_s,
                                  const TouchMapping& mapping, std::vector<InputEvent>& out) {
    if (touch_) {
        touch_->resynchronise(snapshot);
        emit_touch_frame(time_s, mapping, out);
    } else if (kind_ == DeviceKind::pointer) {
        pointer_.resynchronise(snapshot.left_button, time_s, out);
    }
}

void DeviceDecoder::emit_touch_frame(double time_s, const TouchMapping& mapping,
                                     std::vector<InputEvent>& out) const {
    TouchFrame frame{time_s, {}};
    frame.contacts.reserve(touch_->contacts().size());
    for (const NormalisedContact& contact : touch_->contacts())
        frame.contacts.push_back(Contact{contact.id, mapping.to_picture(contact.position)});
    out.push_back(std::move(frame));
}

}  // namespace gem::kiosk
