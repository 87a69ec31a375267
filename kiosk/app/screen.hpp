#pragma once
// The glass and what a frame is drawn on: the display, opened again every few seconds while it
// is missing (said once in the log, then quiet until it works), and the GL objects made with
// it (the HDR picture the scene is drawn into, the picture the display shows, the cross-fade),
// which go before the context that owns them.

#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "display/display.hpp"
#include "display/open_display.hpp"
#include "display/seat.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "passes/crossfade.hpp"
#include "settings/kiosk_config.hpp"

namespace gem::kiosk {

class Screen {
  public:
    Screen(DisplayOptions display, PictureConfig picture, std::shared_ptr<Seat> seat);
    ~Screen() { close(); }
    Screen(const Screen&) = delete;
    Screen& operator=(const Screen&) = delete;

    enum class Opening { unchanged, opened, failed };
    // Tries to open a missing display once its retry is due: `opened` now (what depends on its
    // size follows: the touch mapping, the scene's framing), or `failed` (tried again in a few
    // seconds); `unchanged` when it is open or not yet due.
    Opening open_if_due(double now_s);
    bool open() const { return display_ != nullptr; }
    // When a missing display is tried again.
    double next_try_s() const { return next_try_s_; }

    // While open():
    Display& display() { return *display_; }
    const Display& display() const { return *display_; }
    glm::ivec2 picture_size() const { return display_->picture_size(); }
    gpu::HdrPicture& scene_picture() { return *scene_picture_; }
    const gpu::HdrPicture& scene_picture() const { return *scene_picture_; }
    gpu::RenderTarget& picture() { return *picture_; }
    CrossFade& crossfade() { return *crossfade_; }
    // The HDR picture made again with other options (render.method auto's second probe); an
    // error leaves the one there was.
    Result<bool> remake_scene_picture(const gpu::PictureOptions& options);

    // The GL objects, then the display (which restores the mode the screen had before).
    void close();

  private:
    Result<bool> make_gpu_objects();

    DisplayOptions display_config_;
    PictureConfig picture_config_;
    std::shared_ptr<Seat> seat_;
    std::unique_ptr<Display> display_;
    double next_try_s_ = 0.0;
    bool failure_logged_ = false;
    std::optional<gpu::HdrPicture> scene_picture_;  // radiance, multisampled
    std::optional<gpu::RenderTarget> picture_;      // what the display shows
    std::optional<CrossFade> crossfade_;
};

}  // namespace gem::kiosk
