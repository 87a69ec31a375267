#pragma once
// The kiosk logs to stderr, one line per message, each prefixed with its syslog priority in
// angle brackets ("<3>" for an error), which journald reads as the line's priority
// (sd-daemon(3), "SD_ERR"); on a terminal the prefix is harmless. Lines are written with one
// write() so that threads never interleave within a line.

#include <string_view>

namespace gem::kiosk {

// syslog(3) priorities, as sd-daemon.h numbers them.
enum class LogLevel { error = 3, warning = 4, notice = 5, info = 6, debug = 7 };

void log(LogLevel level, std::string_view message);
inline void log_error(std::string_view message) { log(LogLevel::error, message); }
inline void log_warning(std::string_view message) { log(LogLevel::warning, message); }
inline void log_notice(std::string_view message) { log(LogLevel::notice, message); }
inline void log_info(std::string_view message) { log(LogLevel::info, message); }
inline void log_debug(std::string_view message) { log(LogLevel::debug, message); }

// Messages above this level are dropped (default: info); from config `log_level`.
void set_log_threshold(LogLevel level);

}  // namespace gem::kiosk
