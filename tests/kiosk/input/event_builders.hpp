#pragma once
// Small helpers for writing evdev event lists by hand in tests.

#include <linux/input.h>

namespace gem::kiosk::test {

inline input_event ev(int type, int code, int value, double time_s = 0.0) {
    input_event event{};
    event.input_event_sec = static_cast<decltype(event.input_event_sec)>(time_s);
    event.input_event_usec = static_cast<decltype(event.input_event_usec)>(
        (time_s - static_cast<double>(event.input_event_sec)) * 1e6);
    event.type = static_cast<__u16>(type);
    event.code = static_cast<__u16>(code);
    event.value = value;
    return event;
}
inline input_event abs(int code, int value) {
    return ev(EV_ABS, code, value);
}
inline input_event key(int code, int value) {
    return ev(EV_KEY, code, value);
}
inline input_event syn(double time_s = 0.0) {
    return ev(EV_SYN, SYN_REPORT, 0, time_s);
}
inline input_event mt_report() {
    return ev(EV_SYN, SYN_MT_REPORT, 0);
}
inline input_event dropped() {
    return ev(EV_SYN, SYN_DROPPED, 0);
}

}  // namespace gem::kiosk::test
