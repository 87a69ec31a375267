#include "process_limits.hpp"

#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>

namespace gem::tables {

namespace {

// AddressSanitizer reserves terabytes of address space for its shadow memory, so no address-space
// limit can hold an instrumented build (its first mapping fails).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// The line the new-handler writes, made before any allocation can fail.
char g_out_of_memory[160];
std::size_t g_out_of_memory_size = 0;

void out_of_memory() {
    // No allocation and no stdio here: write(2) and _exit(2) only.
    if (::write(STDERR_FILENO, g_out_of_memory, g_out_of_memory_size) < 0) _exit(3);
    _exit(3);
}

}  // namespace

std::string run_at_idle_priority() {
    std::string refused;
    sched_param none{};
    none.sched_priority = 0;
    if (sched_setscheduler(0, SCHED_IDLE, &none) != 0) {
        refused += std::string("; SCHED_IDLE refused (") + std::strerror(errno) + ")";
    }
    errno = 0;
    if (setpriority(PRIO_PROCESS, 0, 19) != 0) {
        refused += std::string("; nice 19 refused (") + std::strerror(errno) + ")";
    }
    errno = 0;
    const int nice = getpriority(PRIO_PROCESS, 0);
    const bool idle = sched_getscheduler(0) == SCHED_IDLE;
    char line[96];
    std::snprintf(line, sizeof line, "running at %s, nice %d",
                  idle ? "idle CPU priority (SCHED_IDLE)" : "the normal CPU policy",
                  errno == 0 ? nice : 0);
    return line + refused;
}

Result<std::string> limit_memory(std::uint64_t megabytes) {
    if (kAddressSanitizer) {
        return std::string(
            "--memory-mb not applied: this build carries AddressSanitizer, whose "
            "shadow memory needs more address space than any limit");
    }
    const rlim_t bytes = static_cast<rlim_t>(megabytes) << 20;
    // prlimit(2), not setrlimit: the kiosk's unit filters @resources, which holds setrlimit
    // but not prlimit64.
    rlimit limit{};
    if (prlimit(0, RLIMIT_AS, nullptr, &limit) != 0) {
        return Error{std::string("--memory-mb: prlimit: ") + std::strerror(errno)};
    }
    // Only ever lowered: an unprivileged process may not raise its hard limit.
    limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? bytes : std::min(bytes, limit.rlim_max);
    if (prlimit(0, RLIMIT_AS, &limit, nullptr) != 0) {
        return Error{std::string("--memory-mb: prlimit: ") + std::strerror(errno)};
    }
    const int n = std::snprintf(g_out_of_memory, sizeof g_out_of_memory,
                                "gemtables: out of memory: the build may use %llu MB "
                                "(--memory-mb); the database was not written\n",
                                static_cast<unsigned long long>(megabytes));
    g_out_of_memory_size = n > 0 ? std::min<std::size_t>(n, sizeof g_out_of_memory - 1) : 0;
    std::set_new_handler(out_of_memory);
    return std::string();
}

}  // namespace gem::tables
