#include "app/signals.hpp"

#include <signal.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace gem::kiosk {

Result<SignalFd> SignalFd::open() {
    sigset_t set;
    sigemptyset(&set);
    for (int s : {SIGTERM, SIGINT, SIGHUP, SIGUSR1}) sigaddset(&set, s);
    if (pthread_sigmask(SIG_BLOCK, &set, nullptr) != 0) {
        return Error{"cannot block signals: " + std::string(std::strerror(errno))};
    }
    const int fd = signalfd(-1, &set, SFD_NONBLOCK | SFD_CLOEXEC);
    if (fd < 0) return Error{"signalfd: " + std::string(std::strerror(errno))};
    return SignalFd(fd);
}

SignalFd::SignalFd(SignalFd&& other) noexcept : fd_(other.fd_) {
    other.fd_ = -1;
}

SignalFd::~SignalFd() {
    if (fd_ >= 0) ::close(fd_);
}

std::vector<int> SignalFd::take() {
    std::vector<int> signals;
    signalfd_siginfo info;
    while (::read(fd_, &info, sizeof info) == static_cast<ssize_t>(sizeof info)) {
        signals.push_back(static_cast<int>(info.ssi_signo));
    }
    return signals;
}

}  // namespace gem::kiosk
