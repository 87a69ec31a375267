#pragma once
// An eventfd(2) by which a catalogue thread tells the main loop it has something to hand over:
// readable (poll(2) POLLIN) once signalled, until drained.

#include <sys/eventfd.h>
#include <unistd.h>

#include <cstdint>

namespace gem::kiosk {

// Non-blocking and close-on-exec; -1 with errno set where none can be made.
inline int make_event_fd() {
    return ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
}

inline void signal_event_fd(int fd) {
    const std::uint64_t one = 1;
    // Only EAGAIN can fail here (the counter is near 2^64), and then it is readable already.
    [[maybe_unused]] const ssize_t n = ::write(fd, &one, sizeof one);
}

inline void drain_event_fd(int fd) {
    std::uint64_t count = 0;
    [[maybe_unused]] const ssize_t n = ::read(fd, &count, sizeof count);
}

}  // namespace gem::kiosk
