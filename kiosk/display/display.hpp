#pragma once
// Where the kiosk's frames go. The main loop draws every frame into an offscreen picture (a
// gpu::RenderTarget the size of picture_size(), as the shopper sees it) and hands it to
// present(); the DRM backend turns it to the panel's orientation, swaps and queues a page
// flip; the headless backend keeps it for PNG snapshots. Both are driven by the same poll loop:
// wait on event_fd(), call dispatch(), draw when ready().

#include <string>

#include <glm/vec2.hpp>

#include "gpu/egl_context.hpp"
#include "gpu/render_target.hpp"
#include "gpu/tile_set.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

class Display {
  public:
    virtual ~Display() = default;

    // The picture's size in pixels after rotation (what the renderer and the touch mapping use).
    virtual glm::ivec2 picture_size() const = 0;
    // Clockwise rotation from the picture to the panel's scanout (panel orientation + config).
    virtual int rotation_deg() const = 0;
    virtual gpu::EglContext& context() = 0;

    // True when a new frame may be drawn and presented now: no flip pending, DRM master held,
    // an output connected (DRM); the frame timer has fired (headless).
    virtual bool ready() const = 0;
    // True while frames can reach the screen at all: false while switched away to another VT
    // or with the output unplugged (the watchdog then stops waiting for frames).
    virtual bool showing() const { return true; }
    // Shows the picture: true when it was handed to the screen, false when it could not be (a
    // failed modeset, no output), which the caller must not count as a frame shown. Errors are
    // for faults that end the display (the caller logs them); a lost flip or a lost output is
    // handled inside and shows up as ready() staying false. `changed`: the picture's tiles
    // that differ from the last picture presented (y up); the display may draw only those.
    virtual Result<bool> present(const gpu::RenderTarget& picture, const gpu::TileSet& changed) = 0;

    // A file descriptor to poll for input (page-flip events, hotplug, frame timer); -1: none.
    virtual int event_fd() const = 0;
    // Handles whatever made event_fd() readable, and timeouts (flip lost); never blocks.
    virtual void dispatch() = 0;
    // Milliseconds until dispatch() must run even without an event (-1: no deadline).
    virtual int timeout_ms() const = 0;

    // The nominal refresh rate (Hz) of the output, for frame pacing and the watchdog.
    virtual double refresh_hz() const = 0;
    // "DRM /dev/dri/card0 HDMI-A-1 1920x1080@60 atomic" / "headless 1920x1080".
    virtual std::string describe() const = 0;
};

}  // namespace gem::kiosk
