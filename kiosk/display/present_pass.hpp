#pragma once
// Draws the picture into the bound framebuffer (the window surface), turned clockwise by the
// display's rotation and sRGB-encoded by the shader, since the window surface is not an sRGB
// framebuffer (engine/gpu/shaders/present.frag).

#include <optional>

#include <glm/vec2.hpp>

#include "gpu/gl_handles.hpp"
#include "gpu/pixel_rect.hpp"
#include "gpu/program.hpp"
#include "gpu/render_target.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

class PresentPass {
  public:
    static Result<PresentPass> make();
    // Covers the bound framebuffer's (0, 0, scanout) viewport, or only `region` of it (scanout
    // pixels, y up) when given. The picture must be the scanout turned:
    // picture_size_for(scanout, rotation_deg).
    Result<bool> draw(const gpu::RenderTarget& picture, int rotation_deg, glm::ivec2 scanout,
                      const std::optional<gpu::PixelRect>& region = std::nullopt) const;

  private:
    explicit PresentPass(gpu::Program program);
    gpu::Program program_;
    gpu::VertexArray empty_;
};

}  // namespace gem::kiosk
