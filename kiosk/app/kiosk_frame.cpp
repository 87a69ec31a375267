#include "app/kiosk_frame.hpp"

#include <GLES3/gl3.h>

namespace gem::kiosk {

Result<KioskFrame> draw_kiosk_frame(StoneScene* scene, const Camera* camera,
                                    const glm::dvec3& omega, gpu::FrameWait wait,
                                    gpu::HdrPicture& picture, gpu::RenderTarget& target) {
    KioskFrame frame;
    // Around the piece only, where the surround is one colour (hdr_picture.hpp).
    std::optional<gpu::SceneCover> cover;
    if (scene != nullptr && camera != nullptr) cover = scene->renderer().cover(*camera);
    picture.bind(cover);
    glClearColor(0.02f, 0.02f, 0.02f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (scene != nullptr && camera != nullptr) {
        gpu::FrameRenderer& renderer = scene->renderer();
        renderer.prepare(*camera, omega);
        auto stats = renderer.render(*camera, wait, picture.still_frame());
        if (stats) {
            frame.stats = stats.value();
        } else {
            frame.scene_error = stats.error();
        }
    }
    auto finished = picture.finish(target);
    if (!finished) return Error{finished.error()};
    return frame;
}

}  // namespace gem::kiosk
