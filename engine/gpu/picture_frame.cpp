#include "gpu/picture_frame.hpp"

#include <algorithm>

namespace gem::gpu {

Result<FrameStats> draw_picture_frame(FrameRenderer& renderer, HdrPicture& picture,
                                      const CameraSettings& camera, double framing_mm, bool still,
                                      FrameWait wait, const RenderTarget& target) {
    picture.begin_frame(still);
    CameraSettings jittered = camera;
    jittered.shift += picture.jitter_ndc();
    auto moved = Camera::make(jittered, framing_mm, picture.width(), picture.height());
    if (!moved) return Error{moved.error()};
    picture.bind(renderer.cover(moved.value()));
    auto drawn = renderer.render(moved.value(), wait, picture.still_frame());
    if (!drawn) return drawn;
    auto finished = picture.finish(target);
    if (!finished) return Error{finished.error()};
    return drawn;
}

Result<bool> draw_still_picture(FrameRenderer& renderer, HdrPicture& picture,
                                const CameraSettings& camera, double framing_mm,
                                const RenderTarget& target, double* ms) {
    // A moving frame's begin forgets the last view's mean: every frame drawn below is still.
    picture.begin_frame(false);
    const int frames = std::max(picture.options().still_frames, 1);
    for (int f = 0; f < frames; ++f) {
        auto drawn = draw_picture_frame(renderer, picture, camera, framing_mm, true,
                                        FrameWait::frame, target);
        if (!drawn) return Error{drawn.error()};
        if (ms != nullptr) *ms += drawn.value().cpu_ms;
    }
    return true;
}

}  // namespace gem::gpu
