#include "passes/crossfade.hpp"

#include <algorithm>

#include "gpu/gl_check.hpp"
#include "gpu/pipeline.hpp"
#include "passes/pass_programs.hpp"

namespace gem::kiosk {

Result<CrossFade> CrossFade::make(int width, int height) {
    auto program = build_pass_program("fade", "fade.frag");
    if (!program) return Error{program.error()};
    auto held = gpu::RenderTarget::make(width, height);
    if (!held) return Error{held.error()};
    return CrossFade(std::move(program).value(), std::move(held).value());
}

void CrossFade::hold(const gpu::RenderTarget& picture, double now_s, double duration_s) {
    if (duration_s <= 0.0) {
        end_s_ = now_s;
        return;
    }
    // Same size and format: a plain framebuffer blit copies the sRGB bytes unchanged.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, picture.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, held_.framebuffer());
    glBlitFramebuffer(0, 0, picture.width(), picture.height(), 0, 0, held_.width(), held_.height(),
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    picture.bind();
    start_s_ = now_s;
    end_s_ = now_s + duration_s;
}

double CrossFade::opacity(double now_s) const {
    if (now_s >= end_s_) return 0.0;
    return std::clamp((end_s_ - now_s) / (end_s_ - start_s_), 0.0, 1.0);
}

Result<bool> CrossFade::draw(const gpu::RenderTarget& picture, double now_s) const {
    if (!active(now_s)) return true;
    picture.bind();
    const gpu::PipelineScope pass(gpu::Pipeline{&program_, gpu::Blend::alpha});
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, held_.colour_texture());
    program_.set("u_picture", 0);
    program_.set("u_alpha", static_cast<float>(opacity(now_s)));
    glBindVertexArray(empty_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return gpu::gl_check("cross-fade");
}

}  // namespace gem::kiosk
