#pragma once
// One frame of an HDR picture as gemrender, the benches and the tests draw it: the picture's
// frame begun (still or moving), the camera moved by the picture's sub-pixel jitter, the
// renderer's frame drawn with what a still frame traces differently (its wavelengths and
// depth), and the finishing passes into `target`. Drawn `still_frames` times over a view, it is
// the still picture the kiosk shows once the view has settled. (The kiosk draws its own
// frames: its scene frames the camera and its display presents them.)

#include "gpu/frame_renderer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "render/camera.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// `framing_mm`: Camera::make's radius (FrameRenderer::stone_radius_mm() or scene_radius_mm()).
// Errors: the camera's, the renderer's and the finishing passes'.
Result<FrameStats> draw_picture_frame(FrameRenderer& renderer, HdrPicture& picture,
                                      const CameraSettings& camera, double framing_mm, bool still,
                                      FrameWait wait, const RenderTarget& target);

// The still picture of one view, as a new view: the picture's still frames drawn in turn (one
// frame where the picture averages none). `ms`: when given, their summed time (each
// glFinish-bounded).
Result<bool> draw_still_picture(FrameRenderer& renderer, HdrPicture& picture,
                                const CameraSettings& camera, double framing_mm,
                                const RenderTarget& target, double* ms = nullptr);

}  // namespace gem::gpu
