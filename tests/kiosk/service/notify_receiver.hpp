#pragma once
// A stand-in for the service manager's notification socket: an AF_UNIX datagram socket bound
// in a fresh temporary folder, with NOTIFY_SOCKET pointing at it for as long as it lives
// (sd_notify(3) reads the variable on every call).

#include <string>
#include <vector>

namespace gem::kiosk::test {

class NotifyReceiver {
  public:
    NotifyReceiver();
    ~NotifyReceiver();
    NotifyReceiver(const NotifyReceiver&) = delete;
    NotifyReceiver& operator=(const NotifyReceiver&) = delete;

    bool ok() const { return fd_ >= 0; }
    const std::string& path() const { return path_; }
    // Every datagram received since the last call, in order, without waiting.
    std::vector<std::string> take();

  private:
    std::string dir_;
    std::string path_;
    int fd_ = -1;
};

// Sets WATCHDOG_USEC (and WATCHDOG_PID to this process) for sd_watchdog_enabled(3); unsets
// both again when it goes.
class WatchdogEnvironment {
  public:
    explicit WatchdogEnvironment(unsigned long long usec, long pid = 0);
    ~WatchdogEnvironment();
};

}  // namespace gem::kiosk::test
