#include "service/service_notifier.hpp"

#include <algorithm>
#include <string>

#include "service/notify_socket.hpp"

namespace gem::kiosk {

ServiceNotifier::ServiceNotifier() : watchdog_(service_watchdog_interval_s()) {}

void ServiceNotifier::ready(std::string_view status_text) {
    if (ready_sent_) {
        status(status_text);
        return;
    }
    // One datagram, so systemd never sees the service ready without its status.
    notify_service_manager("READY=1\n" + status_assignment(status_text));
    ready_sent_ = true;
}

void ServiceNotifier::status(std::string_view text) {
    notify_service_manager(status_assignment(text));
}

void ServiceNotifier::stopping() {
    notify_service_manager("STOPPING=1");
}

void ServiceNotifier::frame_presented(double now_s) {
    watchdog_.frame_presented(now_s);
}

void ServiceNotifier::set_frames_expected(bool expected) {
    if (expected == watchdog_.frames_expected()) return;
    watchdog_.set_frames_expected(expected);
    if (expected) return;
    if (!ready_sent_) {
        ready("waiting for a display");
    } else {
        status("no display: waiting for one");
    }
}

void ServiceNotifier::tick(double now_s) {
    if (!watchdog_.should_ping(now_s)) return;
    notify_service_manager("WATCHDOG=1");
    watchdog_.pinged(now_s);
}

double ServiceNotifier::next_ping_s(double now_s) const {
    // A ping already overdue is due now.
    return std::max(now_s, watchdog_.next_ping_s());
}

}  // namespace gem::kiosk
