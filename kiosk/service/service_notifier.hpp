#pragma once
// What the kiosk tells systemd (sd_notify(3)): READY=1 once the first frame is on screen,
// STATUS= lines, STOPPING=1 at exit, and WATCHDOG=1 pings that follow frame progress
// (service/watchdog_policy.hpp explains the rule). The unit runs it as Type=notify with
// WatchdogSec= (systemd/gemkiosk.service). Outside systemd every call does nothing.
//
// The main loop calls frame_presented(now) after each frame reaches the screen, tick(now) every
// time round, and wakes no later than next_ping_s(now). Times are seconds on one monotonic
// clock.
//
// No display (unplugged at boot, no DRM master): the app says set_frames_expected(false). If
// that happens before the first frame, READY=1 is sent then, with a status saying the kiosk
// waits for a display: the service is up and doing all it can, and boot (graphical.target,
// which is ordered after it) should not hang until TimeoutStartSec kills a kiosk that is
// merely waiting for a cable. From then on the watchdog follows the main loop's liveness
// until frames are expected again.

#include <string_view>

#include "service/watchdog_policy.hpp"

namespace gem::kiosk {

class ServiceNotifier {
  public:
    // Reads the watchdog interval from the environment systemd set (WATCHDOG_USEC).
    ServiceNotifier();

    // READY=1 with a status line; only the first call sends READY=1, later ones only STATUS=.
    void ready(std::string_view status);
    void status(std::string_view text);
    void stopping();

    void frame_presented(double now_s);
    void set_frames_expected(bool expected);
    void tick(double now_s);
    // When tick() must run next for a ping; infinity when no ping can become due by waiting.
    double next_ping_s(double now_s) const;

    bool ready_sent() const { return ready_sent_; }
    double watchdog_interval_s() const { return 2.0 * watchdog_.period_s(); }

  private:
    WatchdogPolicy watchdog_;
    bool ready_sent_ = false;
};

}  // namespace gem::kiosk
