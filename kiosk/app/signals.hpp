#pragma once
// The signals the kiosk acts on, delivered through a signalfd so the main loop polls them with
// everything else (no work in signal handlers): SIGTERM and SIGINT stop it cleanly (the
// display's previous mode is restored), SIGHUP rescans the catalogue inbox (the systemd path
// unit sends it), SIGUSR1 writes a snapshot of the picture (remote support).

#include <vector>

#include "util/result.hpp"

namespace gem::kiosk {

class SignalFd {
  public:
    // Blocks the signals for the calling thread; call before starting other threads so they
    // inherit the mask.
    static Result<SignalFd> open();
    SignalFd(SignalFd&& other) noexcept;
    SignalFd& operator=(SignalFd&&) = delete;
    ~SignalFd();

    int fd() const { return fd_; }
    std::vector<int> take();  // the signals received since the last call

  private:
    explicit SignalFd(int fd) : fd_(fd) {}
    int fd_ = -1;
};

}  // namespace gem::kiosk
