#pragma once
// An offscreen framebuffer: sRGB 8-bit colour with alpha (GL_SRGB8_ALPHA8, colour-renderable
// in ES 3.0, so shaders write linear light, blending happens in linear light, and the stored
// bytes are sRGB as a display wants) and a depth buffer. read() returns it as a linear Image,
// top row first.

#include "gpu/gl_handles.hpp"
#include "picture/image.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class RenderTarget {
  public:
    // Errors: a size outside the GPU's limits, or an incomplete framebuffer.
    static Result<RenderTarget> make(int width, int height);

    void bind() const;  // as the draw framebuffer, viewport = whole target
    Image read() const;
    GLuint colour_texture() const { return colour_.get(); }
    GLuint framebuffer() const { return framebuffer_.get(); }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    RenderTarget() = default;
    Framebuffer framebuffer_;
    Texture colour_;
    Renderbuffer depth_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace gem::gpu
