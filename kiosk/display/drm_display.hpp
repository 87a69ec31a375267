#pragma once
// The kiosk on a real screen: one connector of one DRM card, driven through GBM and EGL, with
// atomic modesetting where the driver has it (legacy otherwise), page flips that never block
// the loop, hotplug and VT switches handled as normal events (docs/design.md, "Layout": display).
// Frame path: present() draws the picture turned into the GBM window surface, swaps, locks the
// new front buffer, wraps it in a framebuffer and queues a flip; the flip event releases the
// previous buffer and makes the display ready again.

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <xf86drmMode.h>

#include "display/buffer_damage.hpp"
#include "display/display.hpp"
#include "display/display_options.hpp"
#include "display/drm_commit.hpp"
#include "display/present_pass.hpp"
#include "display/seat.hpp"

struct gbm_device;
struct gbm_surface;
struct gbm_bo;
struct udev;
struct udev_monitor;

namespace gem::kiosk {

class DrmDisplay final : public Display {
  public:
    // Tries the cards in order (the first with a connected output that suits the options
    // wins); the error names every card tried and why it was passed over.
    static Result<std::unique_ptr<DrmDisplay>> make(const DisplayOptions& options,
                                                    std::shared_ptr<Seat> seat,
                                                    const std::vector<std::string>& cards);
    ~DrmDisplay() override;
    DrmDisplay(const DrmDisplay&) = delete;
    DrmDisplay& operator=(const DrmDisplay&) = delete;

    glm::ivec2 picture_size() const override;
    int rotation_deg() const override { return rotation_deg_; }
    gpu::EglContext& context() override { return *context_; }
    bool ready() const override;
    bool showing() const override;
    Result<bool> present(const gpu::RenderTarget& picture, const gpu::TileSet& changed) override;
    int event_fd() const override { return epoll_fd_; }
    void dispatch() override;
    int timeout_ms() const override;
    double refresh_hz() const override;
    std::string describe() const override;

  private:
    DrmDisplay() = default;
    Result<bool> open_card(const DisplayOptions& options, const std::string& card);
    static void page_flip_handler(int fd, unsigned sequence, unsigned tv_sec, unsigned tv_usec,
                                  void* user_data);
    void on_page_flip();
    void reprobe();
    void drop_pending_flip();
    void on_seat_disabled();
    void on_seat_enabled();
    void release(gbm_bo*& bo);
    void restore_saved_crtc();
    void watch(int fd);

    using Clock = std::chrono::steady_clock;

    std::shared_ptr<Seat> seat_;
    int listener_id_ = 0;
    std::string card_;
    std::string connector_name_;
    int fd_ = -1;
    KmsOutput output_;
    drmModeCrtc* saved_crtc_ = nullptr;
    gbm_device* gbm_ = nullptr;
    gbm_surface* surface_ = nullptr;
    std::optional<gpu::EglContext> context_;
    std::optional<PresentPass> present_;
    BufferDamage buffer_damage_;
    gpu::TileSet unshown_change_;  // changes of pictures not yet drawn into a buffer
    bool buffer_age_logged_ = false;
    std::unique_ptr<KmsCommit> commit_;
    int rotation_deg_ = 0;
    int flip_timeout_ms_ = 250;

    gbm_bo* current_ = nullptr;  // on screen
    gbm_bo* pending_ = nullptr;  // queued for the next vblank
    Clock::time_point flip_queued_at_{};
    // After a failed modeset (master lost, a monitor refusing the mode) the next try waits
    // until then, so the loop neither spins nor counts unseen frames as shown.
    Clock::time_point modeset_retry_at_{};
    bool needs_modeset_ = true;
    bool lit_once_ = false;
    bool connected_ = true;
    bool flip_lost_logged_ = false;

    int epoll_fd_ = -1;
    udev* udev_ = nullptr;
    udev_monitor* monitor_ = nullptr;
    Clock::time_point next_reprobe_{};  // without udev: poll the connector now and then
};

}  // namespace gem::kiosk
