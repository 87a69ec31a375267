#include "gpu/frame_composer.hpp"

#include <algorithm>

#include <GLES3/gl3.h>

namespace gem::gpu {

namespace {

// At rest between passes (pipeline.hpp), so every mask lets the clear through.
void clear_to_surround() {
    glClearColor(kSurround.x, kSurround.y, kSurround.z, 1.0f);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace

Result<ComposedFrame> compose_frame(const FrameRequest& request, const RenderTarget& target) {
    ComposedFrame frame;
    HdrPicture* picture = request.picture;
    std::optional<Camera> camera;
    if (request.renderer != nullptr && request.view) {
        CameraSettings settings = request.view->camera;
        if (picture != nullptr) settings.shift += picture->jitter_ndc();
        auto made =
            Camera::make(settings, request.view->framing_mm, target.width(), target.height());
        if (made) {
            camera = made.value();
        } else {
            frame.scene_error = "camera: " + made.error();
        }
    }
    if (picture != nullptr) {
        // Around the piece only, where the surround is one colour (hdr_picture.hpp).
        picture->bind(camera ? request.renderer->cover(*camera) : nullptr);
    } else {
        target.bind();
    }
    if (camera) {
        FrameRenderer& renderer = *request.renderer;
        renderer.prepare(*camera, request.view->omega, request.view->wait_for_views);
        const StillFrame still = request.still        ? *request.still
                                 : picture != nullptr ? picture->still_frame()
                                                      : StillFrame{};
        // The scene's own clear (depth, stencil) and background cover every pixel it draws.
        auto stats = renderer.render(*camera, request.wait, still);
        if (stats) {
            frame.stats = stats.value();
        } else {
            frame.scene_error = stats.error();
        }
    }
    if (!frame.stats) clear_to_surround();
    if (picture != nullptr) {
        auto finished =
            picture->finish(target, request.wait == FrameWait::passes ? &frame.finish : nullptr);
        if (!finished) return Error{finished.error()};
    }
    return frame;
}

Result<bool> draw_still_picture(FrameRenderer& renderer, HdrPicture& picture, const FrameView& view,
                                const RenderTarget& target, double* ms) {
    // A moving frame's begin forgets the last view's mean: every frame drawn below is still.
    picture.begin_frame(false);
    const int frames = std::max(picture.options().still_frames, 1);
    for (int f = 0; f < frames; ++f) {
        picture.begin_frame(true);
        auto drawn = compose_frame(
            {.renderer = &renderer, .view = view, .wait = FrameWait::frame, .picture = &picture},
            target);
        if (!drawn) return Error{drawn.error()};
        auto scene = drawn.value().scene();
        if (!scene) return Error{scene.error()};
        if (ms != nullptr) *ms += scene.value().cpu_ms;
    }
    return true;
}

}  // namespace gem::gpu
