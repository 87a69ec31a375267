#include "service/notify_socket.hpp"

#include <systemd/sd-daemon.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "service/log.hpp"

namespace gem::kiosk {

namespace {
bool g_failure_logged = false;
}

bool notify_service_manager(std::string_view assignments) {
    const std::string message(assignments);
    // unset_environment = 0: the environment stays as it is, so every later call (and a
    // restart of the loop) still finds the socket.
    const int sent = sd_notify(0, message.c_str());
    if (sent >= 0) return true;
    if (!g_failure_logged) {
        const char* socket = std::getenv("NOTIFY_SOCKET");
        log_warning(std::string("sd_notify to NOTIFY_SOCKET=") + (socket ? socket : "?") +
                    " failed: " + std::strerror(-sent) + " (further failures not logged)");
        g_failure_logged = true;
    }
    return false;
}

double service_watchdog_interval_s() {
    std::uint64_t usec = 0;
    if (sd_watchdog_enabled(0, &usec) <= 0) return 0.0;
    return static_cast<double>(usec) / 1e6;
}

std::string status_assignment(std::string_view text) {
    std::string line = "STATUS=";
    for (char c : text) line.push_back(c == '\n' ? ' ' : c);
    return line;
}

}  // namespace gem::kiosk
