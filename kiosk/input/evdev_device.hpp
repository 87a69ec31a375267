#pragma once
// One kernel evdev device, read through libevdev over a file descriptor that someone else
// opened (the app may get it from the seat) and will close: this class never closes it.
// Events are timed on CLOCK_MONOTONIC (libevdev_set_clock_id), the kiosk's clock.

#include <memory>
#include <string>
#include <vector>

#include "input/device_decoder.hpp"
#include "input/device_kind.hpp"
#include "input/input_event.hpp"
#include "input/touch_mapping.hpp"
#include "util/result.hpp"

struct libevdev;

namespace gem::kiosk {

// open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC): the fd, or -errno.
int open_device_node(const std::string& path);
void close_device_node(int fd);

class EvdevDevice {
  public:
    // Fails for a file that is not an evdev device, naming the path and the error.
    static Result<std::unique_ptr<EvdevDevice>> create(int fd, const std::string& path);
    ~EvdevDevice();
    EvdevDevice(const EvdevDevice&) = delete;
    EvdevDevice& operator=(const EvdevDevice&) = delete;

    enum class ReadStatus { ok, gone };
    // Reads everything pending (never blocks) and appends what it means to out. gone: the device
    // was unplugged (ENODEV) or failed; it has been logged, and the caller closes it.
    ReadStatus read(const TouchMapping& mapping, std::vector<InputEvent>& out);

    DeviceKind kind() const { return decoder_.kind(); }
    const std::string& name() const { return name_; }
    const std::string& path() const { return path_; }
    int fd() const { return fd_; }

  private:
    EvdevDevice(libevdev* device, int fd, std::string path, DeviceKind kind, const TouchAxes& axes);
    TouchSnapshot snapshot() const;

    libevdev* device_;
    int fd_;
    std::string path_;
    std::string name_;
    DeviceDecoder decoder_;
};

}  // namespace gem::kiosk
