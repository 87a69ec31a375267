#pragma once
// Draws the picture into the bound framebuffer (the window surface), turned clockwise by the
// display's rotation, its sRGB bytes unchanged although the window surface is not an sRGB
// framebuffer (kiosk/passes/shaders/present.frag): copied as they are where the GL can skip
// the sampler's sRGB decode (EXT_texture_sRGB_decode), else decoded and encoded again.

#include <vector>

#include <glm/vec2.hpp>

#include "gpu/gl_handles.hpp"
#include "gpu/pixel_rect.hpp"
#include "gpu/program.hpp"
#include "gpu/rect_draw.hpp"
#include "gpu/render_target.hpp"
#include "gpu/tile_set.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

class PresentPass {
  public:
    enum class Copy {
        bytes,     // the stored bytes, undecoded (needs EXT_texture_sRGB_decode)
        reencode,  // decoded to linear by the sampler, encoded by the shader
    };
    // The copy this GL allows, bytes where it can.
    static Copy supported_copy();
    static Result<PresentPass> make(Copy copy = supported_copy());
    Copy copy() const { return bytes_sampler_ ? Copy::bytes : Copy::reencode; }
    // Covers the bound framebuffer's (0, 0, scanout) viewport, or only the picture's tiles in
    // `region` (turned onto the scanout) when given. The picture must be the scanout turned:
    // picture_size_for(scanout, rotation_deg).
    Result<bool> draw(const gpu::RenderTarget& picture, int rotation_deg, glm::ivec2 scanout,
                      const gpu::TileSet* region = nullptr);

  private:
    PresentPass(gpu::Program program, Copy copy);
    gpu::Program program_;
    gpu::Sampler bytes_sampler_;  // the bytes copy's; none for the re-encoding one
    gpu::RectDraw rect_draw_;
    std::vector<gpu::PixelRect> rects_;  // kept between frames
};

}  // namespace gem::kiosk
