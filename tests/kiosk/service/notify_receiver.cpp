#include "service/notify_receiver.hpp"

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <string>

namespace gem::kiosk::test {

NotifyReceiver::NotifyReceiver() {
    std::string pattern = "/tmp/gemkiosk-notify-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) return;
    dir_ = pattern;
    path_ = dir_ + "/notify";
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd_ < 0) return;
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::strncpy(address.sun_path, path_.c_str(), sizeof address.sun_path - 1);
    if (::bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) < 0) {
        ::close(fd_);
        fd_ = -1;
        return;
    }
    ::setenv("NOTIFY_SOCKET", path_.c_str(), 1);
}

NotifyReceiver::~NotifyReceiver() {
    ::unsetenv("NOTIFY_SOCKET");
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
    if (!dir_.empty()) ::rmdir(dir_.c_str());
}

std::vector<std::string> NotifyReceiver::take() {
    std::vector<std::string> messages;
    std::array<char, 4096> buffer;
    for (;;) {
        const ssize_t length = ::recv(fd_, buffer.data(), buffer.size(), MSG_DONTWAIT);
        if (length < 0) break;
        messages.emplace_back(buffer.data(), static_cast<std::size_t>(length));
    }
    return messages;
}

WatchdogEnvironment::WatchdogEnvironment(unsigned long long usec, long pid) {
    ::setenv("WATCHDOG_USEC", std::to_string(usec).c_str(), 1);
    ::setenv("WATCHDOG_PID", std::to_string(pid != 0 ? pid : static_cast<long>(::getpid())).c_str(),
             1);
}

WatchdogEnvironment::~WatchdogEnvironment() {
    ::unsetenv("WATCHDOG_USEC");
    ::unsetenv("WATCHDOG_PID");
}

}  // namespace gem::kiosk::test
