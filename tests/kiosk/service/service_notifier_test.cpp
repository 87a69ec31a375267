// The datagrams the kiosk sends to systemd, read from a socket standing in for systemd's
// (NOTIFY_SOCKET). Expected messages follow sd_notify(3)'s "KEY=value" lines and the rules in
// kiosk/service/service_notifier.hpp and watchdog_policy.hpp, worked out by hand for each
// sequence of calls.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "service/notify_receiver.hpp"
#include "service/notify_socket.hpp"
#include "service/service_notifier.hpp"

namespace gem::kiosk {
namespace {

using Messages = std::vector<std::string>;

TEST(NotifySocket, DoesNothingWithoutNotifySocket) {
    test::NotifyReceiver receiver;
    ASSERT_TRUE(receiver.ok()) << receiver.path();
    ::unsetenv("NOTIFY_SOCKET");  // the socket exists, but systemd did not name it
    EXPECT_TRUE(notify_service_manager("READY=1"));
    ServiceNotifier notifier;
    notifier.ready("showing");
    notifier.stopping();
    EXPECT_EQ(receiver.take(), Messages{});
}

TEST(NotifySocket, ReportsAMissingSocket) {
    ::setenv("NOTIFY_SOCKET", "/tmp/gemkiosk-no-such-dir/notify", 1);
    EXPECT_FALSE(notify_service_manager("STATUS=x"));
    ::unsetenv("NOTIFY_SOCKET");
}

TEST(ServiceNotifier, ReadyOnceThenStatusAndStopping) {
    test::NotifyReceiver receiver;
    ASSERT_TRUE(receiver.ok()) << receiver.path();
    ServiceNotifier notifier;
    notifier.ready("showing Tolkowsky diamond");
    notifier.ready("showing oval sapphire");
    notifier.status("two\nlines");
    notifier.stopping();
    EXPECT_TRUE(notifier.ready_sent());
    EXPECT_EQ(receiver.take(),
              (Messages{"READY=1\nSTATUS=showing Tolkowsky diamond", "STATUS=showing oval sapphire",
                        "STATUS=two lines", "STOPPING=1"}));
}

TEST(ServiceNotifier, NoWatchdogWithoutWatchdogUsec) {
    test::NotifyReceiver receiver;
    ASSERT_TRUE(receiver.ok());
    ServiceNotifier notifier;
    notifier.frame_presented(1.0);
    notifier.tick(1.0);
    notifier.tick(100.0);
    EXPECT_EQ(receiver.take(), Messages{});
    EXPECT_TRUE(std::isinf(notifier.next_ping_s(0.0)));
}

TEST(ServiceNotifier, NoWatchdogForAnotherProcess) {
    test::NotifyReceiver receiver;
    ASSERT_TRUE(receiver.ok());
    // sd_watchdog_enabled(3): a WATCHDOG_PID that is not ours means the watchdog is not ours.
    test::WatchdogEnvironment watchdog(10'000'000, static_cast<long>(::getpid()) + 1);
    ServiceNotifier notifier;
    notifier.frame_presented(1.0);
    notifier.tick(1.0);
    EXPECT_EQ(receiver.take(), Messages{});
}

TEST(ServiceNotifier, WatchdogPingsFollowFrames) {
    test::NotifyReceiver receiver;
    ASSERT_TRUE(receiver.ok());
    test::WatchdogEnvironment watchdog(10'000'000);  // WatchdogSec=10s: pings >= 5 s apart
    ServiceNotifier notifier;
    EXPECT_DOUBLE_EQ(notifier.watchdog_interval_s(), 10.0);
    notifier.tick(0.0);  // no frame yet
    EXPECT_EQ(receiver.take(), Messages{});
    notifier.frame_presented(0.1);
    notifier.tick(0.1);
    notifier.ready("showing");
    EXPECT_EQ(receiver.take(), (Messages{"WATCHDOG=1", "READY=1\nSTATUS=showing"}));
    notifier.frame_presented(1.0);
    notifier.tick(1.0);  // progress, but only 0.9 s after the ping
    EXPECT_EQ(receiver.take(), Messages{});
    EXPECT_DOUBLE_EQ(notifier.next_ping_s(1.0), 5.1);  // 0.1 + 5
    notifier.tick(5.2);
    EXPECT_EQ(receiver.take(), Messages{"WATCHDOG=1"});
    // Stalled: the loop keeps ticking but no frame reaches the screen.
    for (double t = 5.3; t < 30.0; t += 0.5) notifier.tick(t);
    EXPECT_EQ(receiver.take(), Messages{});
    EXPECT_TRUE(std::isinf(notifier.next_ping_s(30.0)));
    notifier.frame_presented(31.0);
    notifier.tick(31.0);
    EXPECT_EQ(receiver.take(), Messages{"WATCHDOG=1"});
}

TEST(ServiceNotifier, NoDisplayAtStartIsReadyAndPingsOnLiveness) {
    test::NotifyReceiver receiver;
    ASSERT_TRUE(receiver.ok());
    test::WatchdogEnvironment watchdog(4'000'000);  // WatchdogSec=4s: pings >= 2 s apart
    ServiceNotifier notifier;
    notifier.set_frames_expected(false);  // the display did not open
    EXPECT_EQ(receiver.take(), Messages{"READY=1\nSTATUS=waiting for a display"});
    for (double t = 0.0; t <= 5.0; t += 1.0) notifier.tick(t);  // pings at 0, 2, 4
    EXPECT_EQ(receiver.take(), (Messages{"WATCHDOG=1", "WATCHDOG=1", "WATCHDOG=1"}));
    EXPECT_DOUBLE_EQ(notifier.next_ping_s(5.0), 6.0);
    // The display is back: one ping on the strength of the switch, then frames are needed.
    notifier.set_frames_expected(true);
    notifier.tick(6.0);
    notifier.tick(8.0);
    notifier.tick(10.0);
    notifier.ready("showing");  // the first frame: READY=1 went out already
    EXPECT_EQ(receiver.take(), (Messages{"WATCHDOG=1", "STATUS=showing"}));
    // Lost again after having shown frames: a status line, and liveness pings.
    notifier.set_frames_expected(false);
    notifier.tick(10.5);
    EXPECT_EQ(receiver.take(), (Messages{"STATUS=no display: waiting for one", "WATCHDOG=1"}));
}

}  // namespace
}  // namespace gem::kiosk
