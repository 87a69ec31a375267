// The seat through libseat's "noop" backend (chosen with LIBSEAT_BACKEND, libseat.c), which
// opens devices with open(2): the libseat path of Seat without seatd, logind or a VT. (The
// noop backend of libseat 0.7, Debian 12's, never sends enable_seat, so the seat is not
// checked for being active here.)

#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>

#include <fcntl.h>
#include <unistd.h>

#include "display/seat.hpp"

namespace gem::kiosk {
namespace {

TEST(Seat, OpensAndClosesDevicesThroughLibseat) {
    setenv("LIBSEAT_BACKEND", "noop", 1);
    auto seat = Seat::open();
    unsetenv("LIBSEAT_BACKEND");
    ASSERT_TRUE(seat);
    EXPECT_EQ(seat->describe().rfind("libseat ", 0), 0u) << seat->describe();
    EXPECT_GE(seat->fd(), 0);
    const int fd = seat->open("/dev/null");
    ASSERT_GE(fd, 0);
    // The loop polls every descriptor it gets: it must not block.
    EXPECT_NE(fcntl(fd, F_GETFL) & O_NONBLOCK, 0);
    EXPECT_EQ(write(fd, "x", 1), 1);
    seat->close(fd);
    errno = 0;
    EXPECT_EQ(seat->open("/nonexistent/card0"), -1);
    EXPECT_EQ(errno, ENOENT);
    seat->dispatch();  // nothing pending: returns at once
}

}  // namespace
}  // namespace gem::kiosk
