#include "display/seat.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <string>

// libseat.h (0.7) has no extern "C" block of its own.
extern "C" {
#include <libseat.h>
}

#include "service/device_presence.hpp"
#include "service/log.hpp"

namespace gem::kiosk {
namespace {

// Set while closing a device that is already unplugged, whose errors are expected.
bool closing_unplugged_device = false;
// The node being opened: when it turns out to be unplugged, its errors are expected too.
const std::string* opening_path = nullptr;

// libseat's own messages go to our log, one line each, under our priorities.
void log_from_libseat(enum libseat_log_level level, const char* format, va_list args) {
    char text[512];
    std::vsnprintf(text, sizeof text, format, args);
    const std::string message = std::string("libseat: ") + text;
    // A device being opened: its caller reports a failure in its own words (and a node just
    // plugged in may refuse for a moment, input_manager.hpp), so libseat's detail is debug.
    const bool reported = closing_unplugged_device || opening_path != nullptr;
    if (level == LIBSEAT_LOG_LEVEL_ERROR && !reported) {
        log_warning(message);
    } else {
        log_debug(message);
    }
}

// How long open() waits for the seat's first enable event (seatd and logind answer within
// milliseconds; a seat that stays disabled belongs to another VT).
constexpr int kEnableWaitMs = 2000;

}  // namespace

std::shared_ptr<Seat> Seat::open() {
    std::shared_ptr<Seat> seat(new Seat());
    libseat_set_log_handler(log_from_libseat);
    libseat_set_log_level(LIBSEAT_LOG_LEVEL_ERROR);
    static const libseat_seat_listener listener = {&Seat::on_enable, &Seat::on_disable};
    seat->seat_ = libseat_open_seat(&listener, seat.get());
    if (seat->seat_ == nullptr) {
        log_warning(std::string("seat: libseat could not open a seat (") + std::strerror(errno) +
                    "); opening devices directly, which needs root or the video and input "
                    "groups, and no VT switching");
        seat->active_ = true;
        return seat;
    }
    // The enable event comes through dispatch once the backend has granted the session.
    for (int waited = 0; !seat->active_ && waited < kEnableWaitMs; waited += 50) {
        if (libseat_dispatch(seat->seat_, 50) < 0) break;
    }
    if (!seat->active_) {
        log_warning("seat: " + seat->describe() +
                    " is not active yet (another VT?); devices open once it is");
    }
    return seat;
}

Seat::~Seat() {
    if (seat_ == nullptr) return;
    for (const OpenDevice& d : devices_) {
        libseat_close_device(seat_, d.device_id);
        ::close(d.fd);
    }
    libseat_close_seat(seat_);
}

int Seat::open(const std::string& path) {
    if (seat_ == nullptr) {
        return ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    }
    int fd = -1;
    opening_path = &path;
    const int device_id = libseat_open_device(seat_, path.c_str(), &fd);
    opening_path = nullptr;
    if (device_id < 0 || fd < 0) return -1;
    // libseat hands the descriptor over as the backend opened it; the event loop needs it
    // non-blocking.
    const int flags = fcntl(fd, F_GETFL);
    if (flags >= 0) fcntl(fd, F_SETFL, flags | O_NONBLOCK);
    devices_.push_back({fd, device_id});
    return fd;
}

void Seat::close(int fd) {
    if (fd < 0) return;
    if (seat_ != nullptr) {
        for (auto it = devices_.begin(); it != devices_.end(); ++it) {
            if (it->fd == fd) {
                // An unplugged device: logind has already released it and answers "Device not
                // taken" (seen in the VM test); seatd still has to be told. Either way the
                // release is made and its complaint is not a fault.
                closing_unplugged_device = !device_present(fd);
                libseat_close_device(seat_, it->device_id);
                closing_unplugged_device = false;
                devices_.erase(it);
                break;
            }
        }
    }
    ::close(fd);
}

int Seat::fd() const {
    return seat_ != nullptr ? libseat_get_fd(seat_) : -1;
}

void Seat::dispatch() {
    if (seat_ != nullptr && libseat_dispatch(seat_, 0) < 0) {
        log_error(std::string("seat: libseat_dispatch failed: ") + std::strerror(errno));
    }
}

std::string Seat::describe() const {
    if (seat_ == nullptr) return "direct";
    const char* name = libseat_seat_name(seat_);
    return std::string("libseat ") + (name != nullptr ? name : "?");
}

int Seat::add_listener(Listener listener) {
    listeners_.emplace_back(next_listener_, std::move(listener));
    return next_listener_++;
}

void Seat::remove_listener(int id) {
    for (auto it = listeners_.begin(); it != listeners_.end(); ++it) {
        if (it->first == id) {
            listeners_.erase(it);
            return;
        }
    }
}

void Seat::on_enable(struct libseat* /*seat*/, void* self) {
    auto* s = static_cast<Seat*>(self);
    s->active_ = true;
    log_info("seat: " + s->describe() + " enabled");
    for (auto& [id, listener] : s->listeners_) {
        if (listener.enabled) listener.enabled();
    }
}

void Seat::on_disable(struct libseat* seat, void* self) {
    auto* s = static_cast<Seat*>(self);
    s->active_ = false;
    log_info("seat: " + s->describe() + " disabled (VT switch away)");
    for (auto& [id, listener] : s->listeners_) {
        if (listener.disabled) listener.disabled();
    }
    // The backend waits for this before it revokes the devices (libseat.h,
    // libseat_seat_listener::disable_seat).
    libseat_disable_seat(seat);
}

}  // namespace gem::kiosk
