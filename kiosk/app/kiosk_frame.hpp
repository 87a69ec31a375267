#pragma once
// The kiosk's frame, composed in one place: KioskSession draws every frame it shows through
// draw_kiosk_frame, and the method probe (method_probe_run.hpp) times the same function, so the
// probe measures the frame that is shown. In order: the scene picture bound (around what the
// piece covers, where the surround is one colour) and cleared to the kiosk's surround; the stone
// method prepared for the view (the table decodes the views the turn will reach); the scene drawn
// (background, stones, metal); the picture finished (resolve, the still view's mean, glare, tone)
// into `target`.

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "app/stone_scene.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "render/camera.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

struct KioskFrame {
    std::optional<gpu::FrameStats> stats;  // the scene's, when it was drawn
    std::string scene_error;               // why the scene was not drawn (the picture still was)
};

// `scene` and `camera` may be null: the picture shows the surround alone (no stone to show, or
// no camera for it). `omega`: the view's turn in rad/s. An error only when the picture cannot
// be finished; a scene that fails is reported in KioskFrame::scene_error. Leaves `target`
// bound.
Result<KioskFrame> draw_kiosk_frame(StoneScene* scene, const Camera* camera,
                                    const glm::dvec3& omega, gpu::FrameWait wait,
                                    gpu::HdrPicture& picture, gpu::RenderTarget& target);

}  // namespace gem::kiosk
