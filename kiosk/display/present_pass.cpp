#include "display/present_pass.hpp"

#include <cassert>

#include "display/rotation.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"

namespace gem::kiosk {

PresentPass::PresentPass(gpu::Program program)
    : program_(std::move(program)), empty_(gpu::make_vertex_array()) {}

Result<PresentPass> PresentPass::make() {
    auto program = gpu::build_program("present");
    if (!program) return Error{program.error()};
    return PresentPass(std::move(program).value());
}

Result<bool> PresentPass::draw(const gpu::RenderTarget& picture, int rotation_deg,
                               glm::ivec2 scanout,
                               const std::optional<gpu::PixelRect>& region) const {
    const glm::ivec2 picture_size(picture.width(), picture.height());
    assert(picture_size_for(scanout, rotation_deg) == picture_size);
    const PictureFromScanout map = picture_from_scanout(rotation_deg, picture_size);
    glViewport(0, 0, scanout.x, scanout.y);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    program_.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, picture.colour_texture());
    program_.set("u_picture", 0);
    program_.set("u_from_scanout", map.linear);
    program_.set("u_from_scanout_offset", map.offset);
    glBindVertexArray(empty_.get());
    if (region) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(region->x0, region->y0, region->width(), region->height());
    }
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_SCISSOR_TEST);
    return gpu::gl_check("present pass");
}

}  // namespace gem::kiosk
