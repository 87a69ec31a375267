#include "app/screen.hpp"

#include <string>
#include <utility>

#include "display/open_display.hpp"
#include "gpu/visibility_target.hpp"
#include "service/log.hpp"
#include "stage/picture_choice.hpp"

namespace gem::kiosk {

namespace {

// How long a missing display waits before the kiosk tries to open it again.
constexpr double kRetryS = 5.0;

}  // namespace

Screen::Screen(DisplayOptions display, PictureConfig picture, std::shared_ptr<Seat> seat)
    : display_config_(std::move(display)),
      picture_config_(std::move(picture)),
      seat_(std::move(seat)) {}

Screen::Opening Screen::open_if_due(double now_s) {
    if (display_ || now_s < next_try_s_) return Opening::unchanged;
    auto opened = open_display(display_config_, seat_);
    if (!opened) {
        // Said once at error level; the retries every few seconds stay quiet until it works.
        if (!failure_logged_) {
            log_error(opened.error() + "; trying again every " +
                      std::to_string(static_cast<int>(kRetryS)) + " s");
        }
        failure_logged_ = true;
        next_try_s_ = now_s + kRetryS;
        return Opening::failed;
    }
    display_ = std::move(opened).value();
    log_info("display: " + display_->describe() + " on " + display_->context().description());
    if (const std::string note = gpu::multisampled_visibility_note(gpu::max_integer_samples());
        !note.empty()) {
        log_info(note);
    }
    auto made = make_gpu_objects();
    if (!made) {
        log_error(made.error());
        close();
        next_try_s_ = now_s + kRetryS;
        return Opening::failed;
    }
    return Opening::opened;
}

Result<bool> Screen::make_gpu_objects() {
    const glm::ivec2 size = display_->picture_size();
    auto picture = gpu::RenderTarget::make(size.x, size.y);
    if (!picture) return Error{"picture: " + picture.error()};
    picture_.emplace(std::move(picture).value());
    auto scene_picture = gpu::HdrPicture::make(size.x, size.y, picture_options(picture_config_));
    if (!scene_picture) return Error{scene_picture.error()};
    scene_picture_.emplace(std::move(scene_picture).value());
    log_info("picture: " + scene_picture_->describe());
    auto fade = CrossFade::make(size.x, size.y);
    if (!fade) return Error{"cross-fade: " + fade.error()};
    crossfade_.emplace(std::move(fade).value());
    return true;
}

Result<bool> Screen::remake_scene_picture(const gpu::PictureOptions& options) {
    auto remade = gpu::HdrPicture::make(picture_->width(), picture_->height(), options);
    if (!remade) return Error{"picture: " + remade.error()};
    const DisplayTransform display = scene_picture_->options().display;
    scene_picture_.emplace(std::move(remade).value());
    scene_picture_->set_display(display);
    return true;
}

void Screen::close() {
    crossfade_.reset();
    picture_.reset();
    scene_picture_.reset();
    display_.reset();
}

}  // namespace gem::kiosk
