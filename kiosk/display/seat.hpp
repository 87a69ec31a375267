#pragma once
// Access to the seat's devices (DRM cards, /dev/input nodes) without running as root: libseat
// asks seatd or logind for them, or uses its builtin backend, whichever it finds
// (libseat(3) / seatd's libseat.h). When no seat can be opened at all (a container, a test
// machine) devices are opened directly with open(2), and the log says so once.
// A VT switch away disables the seat: the listeners stop using their devices (DRM master is
// gone) before the seat acknowledges; switching back enables it again.

#include <functional>
#include <memory>
#include <string>
#include <vector>

struct libseat;

namespace gem::kiosk {

class Seat {
  public:
    // Never fails: without libseat the seat opens devices directly.
    static std::shared_ptr<Seat> open();
    ~Seat();
    Seat(const Seat&) = delete;
    Seat& operator=(const Seat&) = delete;

    // A file descriptor for the device (read-write, non-blocking, close-on-exec), or -1 with
    // errno set; the caller logs what it was opening and why.
    int open(const std::string& path);
    // Closes a descriptor from open().
    void close(int fd);

    // Pollable when libseat runs the seat; -1 for direct access.
    int fd() const;
    // Handles seat events (enable/disable); never blocks.
    void dispatch();
    // False between a VT switch away and the switch back.
    bool active() const { return active_; }
    // "libseat seat0" or "direct".
    std::string describe() const;

    // Called on disable (before the seat acknowledges it) and on enable. The listener lives
    // until remove_listener(id).
    struct Listener {
        std::function<void()> disabled;
        std::function<void()> enabled;
    };
    int add_listener(Listener listener);
    void remove_listener(int id);

  private:
    Seat() = default;
    static void on_enable(struct libseat* seat, void* self);
    static void on_disable(struct libseat* seat, void* self);

    struct libseat* seat_ = nullptr;
    bool active_ = false;
    struct OpenDevice {
        int fd;
        int device_id;
    };
    std::vector<OpenDevice> devices_;
    std::vector<std::pair<int, Listener>> listeners_;
    int next_listener_ = 1;
};

}  // namespace gem::kiosk
