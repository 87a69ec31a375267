#pragma once
// When the kiosk may tell systemd's watchdog that it is alive (WATCHDOG=1, sd_notify(3)).
//
// A main loop that still turns is not proof that the kiosk works: a hung GPU or a page flip
// that never completes leaves the loop polling forever with a frozen picture. So while frames
// are expected, a ping is sent only if at least one frame reached the screen since the
// previous ping; when frames stop, pings stop, and systemd restarts the service WatchdogSec
// after the last one (systemd.service(5), "WatchdogSec=").
//
// Pings are spaced at least half the watchdog interval W apart, as sd_watchdog_enabled(3)
// advises. A ping at t0 is followed by the next one at max(t0 + W/2, the first frame after t0),
// so frames coming less than W apart always keep the service alive. A frame just before t0
// may still allow a ping at t0 + W/2, so a picture frozen for longer than 1.5 W always gets the
// service restarted (WatchdogSec=10s: within 15 s of the last frame).
//
// Frames are not always expected: after a VT switch the kiosk has lost DRM master, an
// unplugged display has nothing to show on, a display being reopened has not drawn yet. In
// that state the ping needs only the main loop's own liveness (tick() being called): a loop
// stuck in a dead lock or an endless computation still stops the pings. When frames are
// expected again, the switch itself counts as progress once, so the display gets one full
// interval to put its first frame on screen before the rule above applies again.
//
// Pure logic over times in seconds (any monotonic clock); no systemd calls here.

#include <limits>

namespace gem::kiosk {

class WatchdogPolicy {
  public:
    // interval_s: WatchdogSec in seconds; 0 or less disables pinging altogether.
    explicit WatchdogPolicy(double interval_s);

    bool enabled() const { return period_s_ > 0.0; }
    // Half the watchdog interval: the shortest spacing between two pings.
    double period_s() const { return period_s_; }

    void frame_presented(double now_s);
    void set_frames_expected(bool expected);
    bool frames_expected() const { return frames_expected_; }

    // True when a ping is due and allowed now; the caller then sends WATCHDOG=1 and calls
    // pinged(now_s).
    bool should_ping(double now_s) const;
    void pinged(double now_s);

    // The time at which should_ping() next becomes true if nothing else happens, so the main
    // loop can wake for it; infinity when only a new frame can make a ping due (waking up
    // before that would only spin) or when the watchdog is off.
    double next_ping_s() const;

  private:
    bool progress_allows_ping() const { return !frames_expected_ || progressed_; }

    double period_s_ = 0.0;
    double last_ping_s_ = -std::numeric_limits<double>::infinity();
    bool frames_expected_ = true;
    bool progressed_ = false;  // a frame (or a switch to frames expected) since the last ping
};

}  // namespace gem::kiosk
