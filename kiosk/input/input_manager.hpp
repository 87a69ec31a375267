#pragma once
// Every input device of the kiosk: finds the evdev nodes (event* in InputOptions::device_dir, or
// only InputOptions::devices), opens them through an opener the app chooses (the seat's, or
// open(2)), follows devices coming and going with inotify, and hands the main loop one file
// descriptor to poll (an epoll set of the inotify descriptor and every device) and dispatch(),
// which reads everything pending. No device, a missing directory or a device that cannot be
// opened is one log line each; the kiosk keeps running (with only its attract mode, if need be).

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "input/evdev_device.hpp"
#include "input/input_event.hpp"
#include "input/input_options.hpp"
#include "input/touch_mapping.hpp"

namespace gem::kiosk {

// Opens a device node: the file descriptor, or -errno.
using DeviceOpener = std::function<int(const std::string& path)>;
using DeviceCloser = std::function<void(int fd)>;

class InputManager {
  public:
    explicit InputManager(InputOptions options, DeviceOpener open = open_device_node,
                          DeviceCloser close = close_device_node);
    ~InputManager();
    InputManager(const InputManager&) = delete;
    InputManager& operator=(const InputManager&) = delete;

    // The picture the touches map to, and the touch rotation (see TouchMapping).
    void set_mapping(const TouchMapping& mapping) { mapping_ = mapping; }

    // For the main loop's poll(); readable when dispatch() has something to do.
    int fd() const { return epoll_fd_; }
    // Reads hotplug notices and every device's pending events, and tries again to open a new
    // node that is settling; never blocks. Touch times are the devices' own (CLOCK_MONOTONIC);
    // now_s (the same clock) times the retries.
    std::vector<InputEvent> dispatch(double now_s);
    // When dispatch() must run again to retry a settling node, even with nothing to read.
    double next_retry_s() const;

    // A node plugged in may refuse to open for a moment: udev sets its owner and mode after
    // creating it, and logind takes a device only once it has seen udev's notice too (a
    // tablet plugged into the kiosk's VM: "No such device" from logind, then EAGAIN, 0.45 s
    // before it opened). It is tried again every kRetryS, quietly, for kSettleS; still
    // refused after that, the failure is logged once.
    static constexpr double kSettleS = 2.0;
    static constexpr double kRetryS = 0.1;

    // The devices open now, by path.
    std::vector<std::string> open_devices() const;

  private:
    void scan();
    void watch(const std::string& directory);
    void handle_notifications();
    void read_devices(std::vector<InputEvent>& out);  // hotplug notices and devices' events
    bool wanted(const std::string& path) const;
    // Opens `path`: a failure is logged at once during the scan at start; a node plugged in
    // later settles first (kSettleS).
    void add_device(const std::string& path);
    void remove_device(const std::string& path, const char* why);

    InputOptions options_;
    DeviceOpener open_;
    DeviceCloser close_;
    TouchMapping mapping_;
    int epoll_fd_ = -1;
    int inotify_fd_ = -1;
    std::map<int, std::string> watched_dirs_;  // inotify watch -> directory
    std::map<std::string, std::unique_ptr<EvdevDevice>> devices_;
    std::set<std::string> failed_;            // could not be opened, logged; retried on IN_ATTRIB
    std::map<std::string, double> settling_;  // plugged in, refused since; retried quietly
    double now_s_ = 0.0;
    double next_retry_s_ = 0.0;
    bool started_ = false;           // past the scan at start, whose failures are logged at once
    std::set<std::string> ignored_;  // opened and of no use to the kiosk, until deleted
};

}  // namespace gem::kiosk
