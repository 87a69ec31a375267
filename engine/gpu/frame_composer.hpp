#pragma once
// A frame composed in one place: the kiosk, its method probe, gemrender, the tests and every
// bench draw their frames through compose_frame, so a figure any of them prints is a figure
// of the frame the kiosk shows. In order:
//  1. the camera made for the view, moved by the picture's sub-pixel jitter (a still view's
//     frames, HdrPicture::jitter_ndc);
//  2. the picture bound around what the scene covers (FrameRenderer::cover, where its
//     background is one colour), or the target bound where the frame goes straight to it;
//  3. the stone method prepared for the view turning at its angular velocity (the table decodes
//     the views the turn will reach);
//  4. the scene drawn (FrameRenderer::render: its clear, the background, the stones and the
//     metal), tracing what a still frame traces differently (HdrPicture::still_frame);
//     where no scene is drawn (no renderer, no camera, or it failed) the surround is cleared;
//  5. the picture finished (resolve, the still view's mean, glare, tone curve) into the target.
// Beginning a frame (HdrPicture::begin_frame: still or moving) is the caller's: the kiosk asks
// the picture whether a still view needs drawing at all before it composes one.

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "gpu/frame_renderer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "picture/camera.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// What a picture shows where no scene is drawn: the kiosk's dark surround (linear).
inline constexpr glm::vec3 kSurround{0.02f};

// The view a frame shows.
struct FrameView {
    CameraSettings camera{};  // before the picture's jitter
    double framing_mm = 0.0;  // the radius Camera::make fits (FrameRenderer::scene_radius_mm())
    // The view's turn (rad/s) and whether to wait for the views it reaches (a bench that times
    // shading, not decoding): StoneMethod::prepare.
    glm::dvec3 omega{0.0};
    bool wait_for_views = false;
};

struct FrameRequest {
    FrameRenderer* renderer = nullptr;             // null: the surround alone
    std::optional<FrameView> view = std::nullopt;  // nullopt: the surround alone
    // How long the frame waits for the GPU (FrameWait::passes: each pass bounded by glFinish
    // and timed, the finishing passes too).
    FrameWait wait = FrameWait::none;
    // Where the scene is drawn: into this HDR picture, finished into the target; null: straight
    // into the target, unfinished (a stone method's own pixels, as the accuracy study compares
    // them and the stone benches time them).
    HdrPicture* picture = nullptr;
    // What the scene traces differently (depth, wavelengths, still frame's number); nullopt:
    // the picture's still frame (a moving frame's defaults without a picture).
    std::optional<StillFrame> still = std::nullopt;
};

struct ComposedFrame {
    std::optional<FrameStats> stats;  // the scene's, when it was drawn
    std::string scene_error;          // why it was not (the picture still shows the surround)
    FinishTimes finish;               // each finishing pass, with FrameWait::passes
    // The scene's figures, or why it was not drawn: for callers to whom that is an error.
    Result<FrameStats> scene() const {
        if (stats) return *stats;
        return Error{scene_error.empty() ? std::string("no scene to draw") : scene_error};
    }
};

// An error only when the picture cannot be finished. Leaves `target` bound.
Result<ComposedFrame> compose_frame(const FrameRequest& request, const RenderTarget& target);

// The still picture of one view, as a new view: the picture's still frames composed in turn
// (one frame where the picture averages none). `ms`: when given, their summed time (each
// glFinish-bounded).
Result<bool> draw_still_picture(FrameRenderer& renderer, HdrPicture& picture, const FrameView& view,
                                const RenderTarget& target, double* ms = nullptr);

}  // namespace gem::gpu
