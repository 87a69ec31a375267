#include "display/present_pass.hpp"

#include <cassert>

#include <GLES3/gl3.h>
// After gl3.h, whose platform macros it uses: EXT_texture_sRGB_decode's names.
#include <GLES2/gl2ext.h>

#include "display/rotation.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/gl_extensions.hpp"
#include "gpu/pipeline.hpp"
#include "passes/pass_programs.hpp"

namespace gem::kiosk {

PresentPass::PresentPass(gpu::Program program, Copy copy) : program_(std::move(program)) {
    if (copy != Copy::bytes) return;
    // The bytes copy reads through a sampler of its own (a sampler object's decode state
    // overrides the texture's), point-sampled at texel centres: each texel as stored, and
    // the picture itself left decoding for a cross-fade or a snapshot.
    bytes_sampler_ = gpu::make_sampler(GL_NEAREST);
    glSamplerParameteri(bytes_sampler_.get(), GL_TEXTURE_SRGB_DECODE_EXT, GL_SKIP_DECODE_EXT);
}

PresentPass::Copy PresentPass::supported_copy() {
    return gpu::gl_has_extension("GL_EXT_texture_sRGB_decode") ? Copy::bytes : Copy::reencode;
}

Result<PresentPass> PresentPass::make(Copy copy) {
    auto program = copy == Copy::bytes
                       ? build_pass_program("present_bytes", "present.frag", {"PICTURE_BYTES"},
                                            PassCover::rectangles)
                       : build_pass_program("present", "present.frag", {}, PassCover::rectangles);
    if (!program) return Error{program.error()};
    return PresentPass(std::move(program).value(), copy);
}

Result<bool> PresentPass::draw(const gpu::RenderTarget& picture, int rotation_deg,
                               glm::ivec2 scanout, const gpu::TileSet* region) {
    const glm::ivec2 picture_size(picture.width(), picture.height());
    assert(picture_size_for(scanout, rotation_deg) == picture_size);
    const PictureFromScanout map = picture_from_scanout(rotation_deg, picture_size);
    glViewport(0, 0, scanout.x, scanout.y);
    const gpu::PipelineScope pass(gpu::Pipeline{&program_});
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, picture.colour_texture());
    glBindSampler(0, bytes_sampler_.get());  // 0 (none) for the re-encoding copy
    program_.set("u_picture", 0);
    program_.set("u_from_scanout", map.linear);
    program_.set("u_from_scanout_offset", map.offset);
    glDisable(GL_SCISSOR_TEST);
    if (region != nullptr) {
        region->rects(rects_);
        for (gpu::PixelRect& r : rects_) r = scanout_rect(r, rotation_deg, picture_size);
    } else {
        rects_.assign(1, gpu::PixelRect::whole(scanout.x, scanout.y));
    }
    rect_draw_.draw(rects_, scanout);
    glBindSampler(0, 0);
    return gpu::gl_check("present pass");
}

}  // namespace gem::kiosk
