#include "service/process_info.hpp"

#include <time.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace gem::kiosk {

namespace {
double clock_s(clockid_t clock) {
    timespec t{};
    clock_gettime(clock, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}
}  // namespace

double monotonic_now_s() {
    return clock_s(CLOCK_MONOTONIC);
}

double seconds_since_process_start() {
    std::ifstream in("/proc/self/stat");
    std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // The command name (field 2) may hold spaces and parentheses: fields are counted after the
    // last ')'. starttime is field 22, the 20th after the name.
    const auto close = stat.rfind(')');
    if (close == std::string::npos) return 0.0;
    std::istringstream fields(stat.substr(close + 1));
    std::string field;
    for (int i = 0; i < 20 && fields >> field; ++i) {
    }
    const double ticks = std::stod(field.empty() ? "0" : field);
    const double started_s = ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
    return clock_s(CLOCK_BOOTTIME) - started_s;
}

double resident_mib() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("VmRSS:", 0) == 0) {
            std::istringstream value(line.substr(6));
            double kib = 0.0;
            value >> kib;
            return kib / 1024.0;
        }
    }
    return 0.0;
}

}  // namespace gem::kiosk
