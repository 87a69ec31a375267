#include "display/drm_display.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <gbm.h>
#include <libudev.h>
#include <sys/epoll.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xf86drm.h>

#include "display/drm_framebuffer.hpp"
#include "display/drm_probe.hpp"
#include "display/rotation.hpp"
#include "service/log.hpp"

namespace gem::kiosk {
namespace {

// Without a udev monitor the connector's state is read this often (cheaply: the kernel's
// last known state, drmModeGetConnectorCurrent).
constexpr auto kReprobeInterval = std::chrono::seconds(2);

std::string errno_text(int negative_or_positive_errno) {
    return std::strerror(negative_or_positive_errno < 0 ? -negative_or_positive_errno
                                                        : negative_or_positive_errno);
}

// How loud a failed flip or modeset is. EACCES: DRM master was taken away, which logind does
// on a VT switch before the seat's disable event reaches the kiosk (seen in the VM test); that
// event follows and the mode is set again when the seat comes back, so it is no fault.
LogLevel fault_level(int negative_errno) {
    return negative_errno == -EACCES ? LogLevel::info : LogLevel::warning;
}

}  // namespace

Result<std::unique_ptr<DrmDisplay>> DrmDisplay::make(const DisplayOptions& options,
                                                     std::shared_ptr<Seat> seat,
                                                     const std::vector<std::string>& cards) {
    std::unique_ptr<DrmDisplay> d(new DrmDisplay());
    d->seat_ = std::move(seat);
    d->flip_timeout_ms_ = std::max(1, options.flip_timeout_ms);
    std::string passed_over;
    for (const std::string& card : cards) {
        auto opened = d->open_card(options, card);
        if (opened) break;
        passed_over += (passed_over.empty() ? "" : "; ") + card + ": " + opened.error();
    }
    if (d->fd_ < 0) {
        return Error{"DRM display: no usable card (" +
                     (passed_over.empty() ? std::string("none given") : passed_over) + ")"};
    }
    const std::string where = "DRM display " + d->card_ + " " + d->connector_name_ + ": ";

    d->saved_crtc_ = drmModeGetCrtc(d->fd_, d->output_.crtc_id);
    const int width = d->output_.mode.hdisplay;
    const int height = d->output_.mode.vdisplay;
    d->gbm_ = gbm_create_device(d->fd_);
    if (d->gbm_ == nullptr) return Error{where + "gbm_create_device failed"};
    // XRGB8888 is the format every KMS driver scans out; some GBM drivers only make
    // ARGB8888 surfaces (the alpha is ignored by a primary plane without blending).
    std::uint32_t format = GBM_FORMAT_XRGB8888;
    d->surface_ = gbm_surface_create(d->gbm_, width, height, format,
                                     GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
    if (d->surface_ == nullptr) {
        format = GBM_FORMAT_ARGB8888;
        d->surface_ = gbm_surface_create(d->gbm_, width, height, format,
                                         GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
    }
    if (d->surface_ == nullptr) {
        return Error{where + "gbm_surface_create failed for XRGB8888 and ARGB8888 " +
                     std::to_string(width) + "x" + std::to_string(height)};
    }
    auto context = gpu::EglContext::window(EGL_PLATFORM_GBM_KHR, d->gbm_, d->surface_,
                                           static_cast<EGLint>(format));
    if (!context && format == GBM_FORMAT_XRGB8888) {
        // The GBM surface took XRGB8888 but EGL offers no config of that visual: some drivers
        // expose only ARGB8888 configs. Try again with a surface of that format.
        gbm_surface_destroy(d->surface_);
        format = GBM_FORMAT_ARGB8888;
        d->surface_ = gbm_surface_create(d->gbm_, width, height, format,
                                         GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
        if (d->surface_ == nullptr) return Error{where + context.error()};
        context = gpu::EglContext::window(EGL_PLATFORM_GBM_KHR, d->gbm_, d->surface_,
                                          static_cast<EGLint>(format));
    }
    if (!context) return Error{where + context.error()};
    d->context_.emplace(std::move(context).value());
    auto pass = PresentPass::make();
    if (!pass) return Error{where + pass.error()};
    d->present_.emplace(std::move(pass).value());
    if (d->present_->copy() != PresentPass::Copy::bytes) {
        log_info("display: no EXT_texture_sRGB_decode: the present pass decodes and encodes sRGB");
    }

    if (options.atomic) d->commit_ = make_atomic_commit(d->output_);
    if (!d->commit_) d->commit_ = make_legacy_commit(d->output_);

    d->epoll_fd_ = epoll_create1(EPOLL_CLOEXEC);
    if (d->epoll_fd_ < 0) return Error{where + "epoll_create1: " + errno_text(errno)};
    d->watch(d->fd_);
    d->watch(d->seat_->fd());
    d->udev_ = udev_new();
    if (d->udev_ != nullptr) d->monitor_ = udev_monitor_new_from_netlink(d->udev_, "udev");
    if (d->monitor_ != nullptr &&
        (udev_monitor_filter_add_match_subsystem_devtype(d->monitor_, "drm", nullptr) != 0 ||
         udev_monitor_enable_receiving(d->monitor_) != 0)) {
        udev_monitor_unref(d->monitor_);
        d->monitor_ = nullptr;
    }
    if (d->monitor_ != nullptr) {
        d->watch(udev_monitor_get_fd(d->monitor_));
    } else {
        log_info(where + "no udev monitor; checking the connector every 2 s for hotplug");
        d->next_reprobe_ = Clock::now() + kReprobeInterval;
    }
    DrmDisplay* self = d.get();
    d->listener_id_ = d->seat_->add_listener(
        {[self] { self->on_seat_disabled(); }, [self] { self->on_seat_enabled(); }});
    log_info("display: " + d->describe() + " (" + d->context_->description() + ", seat " +
             d->seat_->describe() + ")");
    return d;
}

Result<bool> DrmDisplay::open_card(const DisplayOptions& options, const std::string& card) {
    const int fd = seat_->open(card);
    if (fd < 0) return Error{std::string("cannot open (") + std::strerror(errno) + ")"};
    auto fail = [&](const std::string& why) -> Result<bool> {
        seat_->close(fd);
        return Error{why};
    };
    auto outputs = probe_outputs(fd, card, true);
    if (!outputs) return fail(outputs.error());
    auto choice = choose_output(outputs.value().connectors, options);
    if (!choice) return fail(choice.error());
    const std::size_t c = choice.value().connector;
    const ConnectorInfo& connector = outputs.value().connectors[c];
    auto rotation = total_rotation_deg(connector.orientation, options.rotation_deg);
    if (!rotation) return fail(rotation.error());
    auto crtc = choose_crtc(fd, outputs.value().connector_ids[c]);
    if (!crtc) return fail(connector.name + ": " + crtc.error());
    fd_ = fd;
    card_ = card;
    connector_name_ = connector.name;
    rotation_deg_ = rotation.value();
    output_.fd = fd;
    output_.connector_id = outputs.value().connector_ids[c];
    output_.crtc_id = crtc.value().crtc_id;
    output_.crtc_index = crtc.value().crtc_index;
    output_.mode = outputs.value().modes[c][choice.value().mode];
    return true;
}

DrmDisplay::~DrmDisplay() {
    if (seat_ && listener_id_ != 0) seat_->remove_listener(listener_id_);
    restore_saved_crtc();
    if (saved_crtc_ != nullptr) drmModeFreeCrtc(saved_crtc_);
    present_.reset();
    release(pending_);
    release(current_);
    context_.reset();  // the EGL window surface goes before the GBM surface under it
    if (surface_ != nullptr) gbm_surface_destroy(surface_);  // its buffers' framebuffers too
    if (gbm_ != nullptr) gbm_device_destroy(gbm_);
    commit_.reset();
    if (monitor_ != nullptr) udev_monitor_unref(monitor_);
    if (udev_ != nullptr) udev_unref(udev_);
    if (epoll_fd_ >= 0) close(epoll_fd_);
    if (fd_ >= 0) seat_->close(fd_);
}

void DrmDisplay::watch(int fd) {
    if (fd < 0) return;
    epoll_event event{};
    event.events = EPOLLIN;
    event.data.fd = fd;
    if (epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, fd, &event) != 0) {
        log_error("display: cannot watch descriptor " + std::to_string(fd) + ": " +
                  errno_text(errno));
    }
}

glm::ivec2 DrmDisplay::picture_size() const {
    return picture_size_for({output_.mode.hdisplay, output_.mode.vdisplay}, rotation_deg_);
}

bool DrmDisplay::ready() const {
    return showing() && pending_ == nullptr && Clock::now() >= modeset_retry_at_;
}

bool DrmDisplay::showing() const {
    return seat_->active() && connected_;
}

Result<bool> DrmDisplay::present(const gpu::RenderTarget& picture, const gpu::TileSet& changed) {
    // A picture not shown leaves its change for the next one to show.
    if (unshown_change_.width() != changed.width() ||
        unshown_change_.height() != changed.height()) {
        unshown_change_.reset(changed.width(), changed.height());
    }
    unshown_change_.add(changed);
    if (!ready()) return false;
    const glm::ivec2 scanout(output_.mode.hdisplay, output_.mode.vdisplay);
    if (glm::ivec2(picture.width(), picture.height()) != picture_size()) {
        return Error{"DRM display: picture is " + std::to_string(picture.width()) + "x" +
                     std::to_string(picture.height()) + ", expected " +
                     std::to_string(picture_size().x) + "x" + std::to_string(picture_size().y)};
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    // Only what this back buffer lacks (buffer_damage.hpp); all of it where EGL cannot say.
    const std::optional<int> age = context_->buffer_age();
    if (!age && !buffer_age_logged_) {
        log_info("display: no EGL_EXT_buffer_age: every frame draws the whole screen");
        buffer_age_logged_ = true;
    }
    const gpu::TileSet& region = buffer_damage_.repaint(age, unshown_change_);
    auto drawn = present_->draw(picture, rotation_deg_, scanout, &region);
    unshown_change_.reset(picture.width(), picture.height());
    if (!drawn) return Error{drawn.error()};
    auto swapped = context_->swap_buffers();
    if (!swapped) return Error{"DRM display: " + swapped.error()};
    gbm_bo* bo = gbm_surface_lock_front_buffer(surface_);
    if (bo == nullptr) return Error{"DRM display: gbm_surface_lock_front_buffer failed"};
    const std::uint32_t fb = framebuffer_for(fd_, bo);
    if (fb == 0) {
        const int error = errno;
        release(bo);
        return Error{"DRM display " + card_ + ": drmModeAddFB2 failed: " + errno_text(error)};
    }
    if (needs_modeset_) {
        const int r = commit_->modeset(fb);
        if (r != 0) {
            release(bo);
            const std::string message = "DRM display " + card_ + " " + connector_name_ + ": " +
                                        commit_->name() + " modeset failed: " + errno_text(r);
            if (!lit_once_) return Error{message};
            // Lost master or a monitor that refuses the mode: try again in a second, quietly.
            if (!flip_lost_logged_) log(fault_level(r), message + "; retrying every second");
            flip_lost_logged_ = true;
            modeset_retry_at_ = Clock::now() + std::chrono::seconds(1);
            return false;
        }
        release(current_);
        current_ = bo;
        needs_modeset_ = false;
        flip_lost_logged_ = false;
        if (!lit_once_) log_info("display: " + describe() + " lit");
        lit_once_ = true;
        return true;
    }
    const int r = commit_->flip(fb, this);
    if (r == 0) {
        pending_ = bo;
        flip_queued_at_ = Clock::now();
        return true;
    }
    release(bo);
    // EBUSY: the driver still has a flip in flight (ours was dropped as lost); next frame.
    if (r == -EBUSY) return true;
    needs_modeset_ = true;
    log(fault_level(r), "DRM display " + card_ + " " + connector_name_ + ": page flip failed (" +
                            errno_text(r) + "); setting the mode again");
    return true;
}

void DrmDisplay::page_flip_handler(int /*fd*/, unsigned /*sequence*/, unsigned /*tv_sec*/,
                                   unsigned /*tv_usec*/, void* user_data) {
    static_cast<DrmDisplay*>(user_data)->on_page_flip();
}

void DrmDisplay::on_page_flip() {
    // A late event for a flip already given up as lost finds nothing pending.
    if (pending_ == nullptr) return;
    release(current_);
    current_ = pending_;
    pending_ = nullptr;
}

void DrmDisplay::dispatch() {
    epoll_event events[4];
    const int n = epoll_wait(epoll_fd_, events, 4, 0);
    bool hotplug = false;
    for (int i = 0; i < n; ++i) {
        const int fd = events[i].data.fd;
        if (fd == fd_) {
            drmEventContext handlers{};
            handlers.version = 2;
            handlers.page_flip_handler = page_flip_handler;
            drmHandleEvent(fd_, &handlers);
        } else if (fd == seat_->fd()) {
            seat_->dispatch();
        } else if (monitor_ != nullptr && fd == udev_monitor_get_fd(monitor_)) {
            while (udev_device* device = udev_monitor_receive_device(monitor_)) {
                // By device number, not path: the card may have been named through a
                // symlink such as /dev/dri/by-path/...
                struct stat card {};
                if (::fstat(fd_, &card) == 0 && udev_device_get_devnum(device) == card.st_rdev) {
                    hotplug = true;
                }
                udev_device_unref(device);
            }
        }
    }
    const auto now = Clock::now();
    if (pending_ != nullptr &&
        now - flip_queued_at_ > std::chrono::milliseconds(flip_timeout_ms_)) {
        if (!flip_lost_logged_) {
            log_warning("DRM display " + card_ + " " + connector_name_ +
                        ": page flip not done in " + std::to_string(flip_timeout_ms_) +
                        " ms; treating it as lost and setting "
                        "the mode again");
        }
        flip_lost_logged_ = true;
        drop_pending_flip();
        needs_modeset_ = true;
    }
    if (monitor_ == nullptr && now >= next_reprobe_) {
        next_reprobe_ = now + kReprobeInterval;
        hotplug = true;
    }
    if (hotplug) reprobe();
}

int DrmDisplay::timeout_ms() const {
    using std::chrono::duration_cast;
    using std::chrono::milliseconds;
    const auto now = Clock::now();
    long t = -1;
    if (pending_ != nullptr) {
        const auto deadline = flip_queued_at_ + milliseconds(flip_timeout_ms_ + 1);
        t = std::max(0L, static_cast<long>(duration_cast<milliseconds>(deadline - now).count()));
    }
    if (now < modeset_retry_at_) {
        const long r =
            static_cast<long>(duration_cast<milliseconds>(modeset_retry_at_ - now).count() + 1);
        t = t < 0 ? r : std::min(t, r);
    }
    if (monitor_ == nullptr) {
        const long r = std::max(
            0L, static_cast<long>(duration_cast<milliseconds>(next_reprobe_ - now).count()));
        t = t < 0 ? r : std::min(t, r);
    }
    return static_cast<int>(t);
}

void DrmDisplay::drop_pending_flip() {
    // Which buffer is on screen is unknown; keep the queued one locked (it may be scanning
    // out) and give back the older one. The next modeset replaces both.
    if (pending_ == nullptr) return;
    release(current_);
    current_ = pending_;
    pending_ = nullptr;
}

void DrmDisplay::reprobe() {
    // After a udev event the kernel has probed already; polling only reads its state.
    auto outputs = probe_outputs(fd_, card_, /*force=*/monitor_ == nullptr);
    if (!outputs) return;
    bool now_connected = false;
    bool mode_offered = false;
    for (std::size_t i = 0; i < outputs.value().connector_ids.size(); ++i) {
        if (outputs.value().connector_ids[i] != output_.connector_id) continue;
        now_connected = outputs.value().connectors[i].connected;
        for (const drmModeModeInfo& m : outputs.value().modes[i]) {
            if (m.hdisplay == output_.mode.hdisplay && m.vdisplay == output_.mode.vdisplay) {
                mode_offered = true;
            }
        }
    }
    if (connected_ && !now_connected) {
        log_warning("display: " + connector_name_ + " on " + card_ +
                    " disconnected; waiting for it to come back");
        drop_pending_flip();
        connected_ = false;
    } else if (!connected_ && now_connected) {
        log_info("display: " + connector_name_ + " on " + card_ + " reconnected");
        if (!mode_offered) {
            log_warning("display: " + connector_name_ + " no longer lists " +
                        std::to_string(output_.mode.hdisplay) + "x" +
                        std::to_string(output_.mode.vdisplay) + "; trying it anyway");
        }
        connected_ = true;
        needs_modeset_ = true;
    }
}

void DrmDisplay::on_seat_disabled() {
    // Master is gone: no flip event will come for a queued flip, and nothing may be committed
    // until the seat is back.
    drop_pending_flip();
    needs_modeset_ = true;
}

void DrmDisplay::on_seat_enabled() {
    // Whoever had the VT may have changed the CRTC; set ours again. Hotplugs may have been
    // missed meanwhile.
    needs_modeset_ = true;
    reprobe();
}

void DrmDisplay::release(gbm_bo*& bo) {
    if (bo != nullptr && surface_ != nullptr) gbm_surface_release_buffer(surface_, bo);
    bo = nullptr;
}

void DrmDisplay::restore_saved_crtc() {
    if (saved_crtc_ == nullptr || !lit_once_ || fd_ < 0 || !seat_->active()) return;
    // What the console (or whoever was before us) showed; a CRTC that was off stays off.
    std::uint32_t connector = output_.connector_id;
    const int r =
        saved_crtc_->mode_valid
            ? drmModeSetCrtc(fd_, saved_crtc_->crtc_id, saved_crtc_->buffer_id, saved_crtc_->x,
                             saved_crtc_->y, &connector, 1, &saved_crtc_->mode)
            : drmModeSetCrtc(fd_, saved_crtc_->crtc_id, 0, 0, 0, nullptr, 0, nullptr);
    if (r != 0)
        log_warning("display: restoring the CRTC on " + card_ + " failed: " + errno_text(r));
}

double DrmDisplay::refresh_hz() const {
    return mode_refresh_hz(mode_info_from(output_.mode));
}

std::string DrmDisplay::describe() const {
    std::string text = "DRM " + card_ + " " + connector_name_ + " " +
                       describe_mode(mode_info_from(output_.mode)) + " " +
                       (commit_ ? commit_->name() : "?");
    if (rotation_deg_ != 0) text += " rotated " + std::to_string(rotation_deg_);
    return text;
}

}  // namespace gem::kiosk
