#include "input/input_manager.hpp"

#include <sys/epoll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>

#include "service/device_presence.hpp"
#include "service/log.hpp"

namespace gem::kiosk {

namespace {

std::string error_text(int error) {
    return std::strerror(error);
}

bool is_event_node_name(const std::string& name) {
    return name.rfind("event", 0) == 0;
}

}  // namespace

InputManager::InputManager(InputOptions options, DeviceOpener open, DeviceCloser close)
    : options_(std::move(options)), open_(std::move(open)), close_(std::move(close)) {
    epoll_fd_ = ::epoll_create1(EPOLL_CLOEXEC);
    inotify_fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (epoll_fd_ < 0 || inotify_fd_ < 0) {
        log_error("input: cannot set up device hotplug (" + error_text(errno) +
                  "); devices present now are used, new ones are not noticed");
    } else {
        epoll_event event{};
        event.events = EPOLLIN;
        event.data.fd = inotify_fd_;
        ::epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, inotify_fd_, &event);
    }
    // Watch before scanning so that a device appearing in between is not missed.
    std::set<std::string> directories;
    if (options_.devices.empty()) {
        directories.insert(options_.device_dir);
    } else {
        for (const std::string& device : options_.devices)
            directories.insert(std::filesystem::path(device).parent_path().string());
    }
    for (const std::string& directory : directories) watch(directory);
    scan();
    started_ = true;
}

InputManager::~InputManager() {
    for (auto& [path, device] : devices_) close_(device->fd());
    if (inotify_fd_ >= 0) ::close(inotify_fd_);
    if (epoll_fd_ >= 0) ::close(epoll_fd_);
}

void InputManager::watch(const std::string& directory) {
    if (inotify_fd_ < 0) return;
    const int watch = ::inotify_add_watch(inotify_fd_, directory.c_str(),
                                          IN_CREATE | IN_ATTRIB | IN_DELETE | IN_MOVED_TO);
    if (watch < 0) {
        log_warning("input: cannot watch " + directory + " for devices: " + error_text(errno) +
                    "; carrying on without its devices");
        return;
    }
    watched_dirs_[watch] = directory;
}

void InputManager::scan() {
    if (!options_.devices.empty()) {
        for (const std::string& device : options_.devices) add_device(device);
        return;
    }
    std::error_code error;
    std::vector<std::string> paths;
    for (const auto& entry : std::filesystem::directory_iterator(options_.device_dir, error)) {
        if (is_event_node_name(entry.path().filename().string()))
            paths.push_back(entry.path().string());
    }
    // A missing directory was reported by watch() already.
    std::sort(paths.begin(), paths.end());
    for (const std::string& path : paths) add_device(path);
}

bool InputManager::wanted(const std::string& path) const {
    if (!options_.devices.empty())
        return std::find(options_.devices.begin(), options_.devices.end(), path) !=
               options_.devices.end();
    return is_event_node_name(std::filesystem::path(path).filename().string());
}

void InputManager::add_device(const std::string& path) {
    if (devices_.count(path) != 0 || ignored_.count(path) != 0) return;
    const int fd = open_(path);
    if (fd < 0) {
        // A device unplugged as it was plugged in (udev's last change to a node can reach us
        // after the kernel has dropped the device) is no fault.
        if (!device_present(path)) {
            log_debug("input device " + path + ": gone before it could be opened");
            return;
        }
        if (started_) {
            // Plugged in while running: settling for a moment is expected.
            const double since = settling_.emplace(path, now_s_).first->second;
            if (now_s_ - since < kSettleS) {
                log_debug("input device " + path + ": not open yet: " + error_text(-fd));
                return;
            }
            settling_.erase(path);
        }
        if (failed_.insert(path).second)
            log_warning("input device " + path + ": cannot open: " + error_text(-fd));
        return;
    }
    failed_.erase(path);
    settling_.erase(path);
    Result<std::unique_ptr<EvdevDevice>> created = EvdevDevice::create(fd, path);
    if (!created) {
        log_warning(created.error());
        close_(fd);
        ignored_.insert(path);
        return;
    }
    std::unique_ptr<EvdevDevice> device = std::move(created.value());
    if (device->kind() == DeviceKind::other) {
        log_debug("input device " + path + " (" + device->name() + "): not used by the kiosk");
        close_(fd);
        ignored_.insert(path);
        return;
    }
    epoll_event event{};
    event.events = EPOLLIN;
    event.data.fd = fd;
    if (epoll_fd_ >= 0 && ::epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, fd, &event) < 0) {
        log_warning("input device " + path + ": cannot poll: " + error_text(errno));
        close_(fd);
        ignored_.insert(path);
        return;
    }
    log_info("input device " + path + " (" + device->name() +
             "): " + std::string(to_string(device->kind())));
    devices_[path] = std::move(device);
}

void InputManager::remove_device(const std::string& path, const char* why) {
    failed_.erase(path);
    settling_.erase(path);
    ignored_.erase(path);
    const auto found = devices_.find(path);
    if (found == devices_.end()) return;
    if (epoll_fd_ >= 0) ::epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, found->second->fd(), nullptr);
    close_(found->second->fd());
    if (why != nullptr) log_info("input device " + path + " " + why);
    devices_.erase(found);
}

void InputManager::handle_notifications() {
    // inotify(7): a buffer aligned for inotify_event, large enough for several events.
    alignas(inotify_event) std::array<char, 4096> buffer;
    for (;;) {
        const ssize_t length = ::read(inotify_fd_, buffer.data(), buffer.size());
        if (length <= 0) return;
        for (ssize_t offset = 0; offset < length;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer.data() + offset);
            offset += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            if (event->mask & IN_Q_OVERFLOW) {
                // Notices were lost (inotify(7)): look at the directory afresh.
                scan();
                continue;
            }
            const auto directory = watched_dirs_.find(event->wd);
            if (directory == watched_dirs_.end() || event->len == 0) continue;
            const std::string path = directory->second + "/" + event->name;
            if (!wanted(path)) continue;
            if (event->mask & IN_DELETE) {
                remove_device(path, "removed");
            } else if (event->mask & (IN_CREATE | IN_MOVED_TO | IN_ATTRIB)) {
                // New, or udev has set its owner and mode after creating it: try (again) now.
                add_device(path);
            }
        }
    }
}

double InputManager::next_retry_s() const {
    return settling_.empty() ? std::numeric_limits<double>::infinity() : next_retry_s_;
}

std::vector<InputEvent> InputManager::dispatch(double now_s) {
    now_s_ = now_s;
    std::vector<InputEvent> out;
    if (!settling_.empty() && now_s >= next_retry_s_) {
        std::vector<std::string> retry;
        for (const auto& [path, since] : settling_) retry.push_back(path);
        for (const std::string& path : retry) add_device(path);
        next_retry_s_ = now_s + kRetryS;
    }
    read_devices(out);
    // A node that began settling just now is first tried again a step later.
    if (!settling_.empty() && next_retry_s_ <= now_s) next_retry_s_ = now_s + kRetryS;
    return out;
}

void InputManager::read_devices(std::vector<InputEvent>& out) {
    if (epoll_fd_ < 0) return;
    std::array<epoll_event, 16> ready;
    std::vector<std::string> gone;
    int count = 0;
    do {
        count = ::epoll_wait(epoll_fd_, ready.data(), static_cast<int>(ready.size()), 0);
        for (int i = 0; i < count; ++i) {
            const int fd = ready[static_cast<std::size_t>(i)].data.fd;
            if (fd == inotify_fd_) {
                handle_notifications();
                continue;
            }
            for (auto& [path, device] : devices_) {
                if (device->fd() != fd) continue;
                if (device->read(mapping_, out) == EvdevDevice::ReadStatus::gone)
                    gone.push_back(path);
                break;
            }
        }
        for (const std::string& path : gone) remove_device(path, nullptr);
        gone.clear();
    } while (count == static_cast<int>(ready.size()));
}

std::vector<std::string> InputManager::open_devices() const {
    std::vector<std::string> paths;
    for (const auto& [path, device] : devices_) paths.push_back(path);
    return paths;
}

}  // namespace gem::kiosk
