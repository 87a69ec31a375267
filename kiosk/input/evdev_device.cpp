#include "input/evdev_device.hpp"

#include <fcntl.h>
#include <libevdev/libevdev.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "service/log.hpp"

namespace gem::kiosk {

namespace {

AxisRange axis_range(libevdev* device, unsigned int code) {
    const input_absinfo* info = libevdev_get_abs_info(device, code);
    if (info == nullptr) return {};
    return {info->minimum, info->maximum};
}

DeviceCapabilities capabilities_of(libevdev* d) {
    DeviceCapabilities c;
    c.direct = libevdev_has_property(d, INPUT_PROP_DIRECT) != 0;
    c.mt_position = libevdev_has_event_code(d, EV_ABS, ABS_MT_POSITION_X) &&
                    libevdev_has_event_code(d, EV_ABS, ABS_MT_POSITION_Y);
    c.mt_slot = libevdev_has_event_code(d, EV_ABS, ABS_MT_SLOT) != 0;
    c.abs_xy =
        libevdev_has_event_code(d, EV_ABS, ABS_X) && libevdev_has_event_code(d, EV_ABS, ABS_Y);
    c.btn_touch = libevdev_has_event_code(d, EV_KEY, BTN_TOUCH) != 0;
    c.rel_xy =
        libevdev_has_event_code(d, EV_REL, REL_X) && libevdev_has_event_code(d, EV_REL, REL_Y);
    c.btn_left = libevdev_has_event_code(d, EV_KEY, BTN_LEFT) != 0;
    c.typing_keys =
        libevdev_has_event_code(d, EV_KEY, KEY_A) && libevdev_has_event_code(d, EV_KEY, KEY_ENTER);
    c.mt_x = axis_range(d, ABS_MT_POSITION_X);
    c.mt_y = axis_range(d, ABS_MT_POSITION_Y);
    c.abs_x = axis_range(d, ABS_X);
    c.abs_y = axis_range(d, ABS_Y);
    c.slot_maximum = axis_range(d, ABS_MT_SLOT).maximum;
    return c;
}

}  // namespace

int open_device_node(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    return fd >= 0 ? fd : -errno;
}

void close_device_node(int fd) {
    ::close(fd);
}

Result<std::unique_ptr<EvdevDevice>> EvdevDevice::create(int fd, const std::string& path) {
    libevdev* device = nullptr;
    const int rc = libevdev_new_from_fd(fd, &device);
    if (rc < 0) {
        return Error{"input device " + path + ": not an evdev device (" + std::strerror(-rc) + ")"};
    }
    // Event times on the kiosk's clock rather than the wall clock, which NTP may step.
    if (libevdev_set_clock_id(device, CLOCK_MONOTONIC) < 0)
        log_warning("input device " + path + ": cannot switch to CLOCK_MONOTONIC timestamps");
    const DeviceCapabilities capabilities = capabilities_of(device);
    const DeviceKind kind = classify(capabilities);
    if (kind == DeviceKind::keyboard) {
        // Grabbed so that no other reader, the text console included, sees what is typed.
        if (libevdev_grab(device, LIBEVDEV_GRAB) < 0)
            log_warning("input device " + path + ": cannot grab the keyboard");
    }
    return std::unique_ptr<EvdevDevice>(
        new EvdevDevice(device, fd, path, kind, touch_axes(capabilities)));
}

EvdevDevice::EvdevDevice(libevdev* device, int fd, std::string path, DeviceKind kind,
                         const TouchAxes& axes)
    : device_(device),
      fd_(fd),
      path_(std::move(path)),
      name_(libevdev_get_name(device) ? libevdev_get_name(device) : ""),
      decoder_(kind, axes) {}

EvdevDevice::~EvdevDevice() {
    libevdev_free(device_);
}

TouchSnapshot EvdevDevice::snapshot() const {
    TouchSnapshot s;
    const int slots = libevdev_get_num_slots(device_);
    for (int slot = 0; slot < slots; ++slot) {
        s.slots.push_back({libevdev_get_slot_value(device_, slot, ABS_MT_TRACKING_ID),
                           libevdev_get_slot_value(device_, slot, ABS_MT_POSITION_X),
                           libevdev_get_slot_value(device_, slot, ABS_MT_POSITION_Y)});
    }
    s.current_slot = slots > 0 ? libevdev_get_current_slot(device_) : 0;
    s.x = libevdev_get_event_value(device_, EV_ABS, ABS_X);
    s.y = libevdev_get_event_value(device_, EV_ABS, ABS_Y);
    s.touching = libevdev_get_event_value(device_, EV_KEY, BTN_TOUCH) != 0;
    s.left_button = libevdev_get_event_value(device_, EV_KEY, BTN_LEFT) != 0;
    return s;
}

EvdevDevice::ReadStatus EvdevDevice::read(const TouchMapping& mapping,
                                          std::vector<InputEvent>& out) {
    const auto state = [this] { return snapshot(); };
    int rc = 0;
    for (;;) {
        input_event event{};
        rc = libevdev_next_event(device_, LIBEVDEV_READ_FLAG_NORMAL, &event);
        if (rc == LIBEVDEV_READ_STATUS_SUCCESS) {
            decoder_.feed(event, mapping, state, out);
            continue;
        }
        if (rc == LIBEVDEV_READ_STATUS_SYNC) {
            // SYN_DROPPED: libevdev has queried the kernel and queued the events that bring its
            // own state up to date; reading them (LIBEVDEV_READ_FLAG_SYNC) applies them. Their
            // sum is what the device is now, which is all the decoder needs.
            const double time_s = event_time_s(event);
            do {
                rc = libevdev_next_event(device_, LIBEVDEV_READ_FLAG_SYNC, &event);
            } while (rc == LIBEVDEV_READ_STATUS_SYNC);
            if (rc != -EAGAIN) break;
            log_info("input device " + path_ + ": events dropped by the kernel, resynchronised");
            decoder_.resynchronise(snapshot(), time_s, mapping, out);
            continue;
        }
        if (rc == -EAGAIN) return ReadStatus::ok;
        break;
    }
    // Read errors other than EAGAIN: ENODEV when unplugged, anything else is as final.
    log_info("input device " + path_ + " (" + name_ + ") gone: " + std::strerror(-rc));
    return ReadStatus::gone;
}

}  // namespace gem::kiosk
