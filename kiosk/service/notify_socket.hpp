#pragma once
// The service manager's notification socket, through libsystemd's sd_notify(3): one datagram
// of newline-separated "KEY=value" assignments per call. Outside systemd (NOTIFY_SOCKET unset:
// a terminal, CI, tests) every call does nothing and succeeds.

#include <string>
#include <string_view>

namespace gem::kiosk {

// Sends the assignments as one datagram. False when NOTIFY_SOCKET is set but the message could
// not be sent; the first such failure is logged with the socket's address and the reason, later
// ones are not (the kiosk sends on every watchdog period and would flood the journal).
bool notify_service_manager(std::string_view assignments);

// WatchdogSec of the service in seconds from WATCHDOG_USEC/WATCHDOG_PID
// (sd_watchdog_enabled(3)); 0 when the watchdog is off or meant for another process.
double service_watchdog_interval_s();

// "STATUS=" followed by the text with newlines turned into spaces: a newline would end the
// assignment and start another (sd_notify(3)).
std::string status_assignment(std::string_view text);

}  // namespace gem::kiosk
