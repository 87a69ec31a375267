#include "service/log.hpp"

#include <unistd.h>

#include <atomic>
#include <string>

namespace gem::kiosk {

namespace {
std::atomic<int> g_threshold{static_cast<int>(LogLevel::info)};
}

void set_log_threshold(LogLevel level) { g_threshold = static_cast<int>(level); }

void log(LogLevel level, std::string_view message) {
    if (static_cast<int>(level) > g_threshold.load()) return;
    std::string line = "<" + std::to_string(static_cast<int>(level)) + ">gemkiosk: ";
    line.append(message);
    line.push_back('\n');
    // One write per line; a short write to stderr is not retried (nothing better to do).
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line.data(), line.size());
}

}  // namespace gem::kiosk
