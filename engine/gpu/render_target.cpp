#include "gpu/render_target.hpp"

#include <cmath>
#include <vector>

#include "gpu/gl_check.hpp"

namespace gem::gpu {

Result<RenderTarget> RenderTarget::make(int width, int height) {
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (width < 1 || height < 1 || width > max_size || height > max_size) {
        return Error{"render target: " + std::to_string(width) + "×" + std::to_string(height) +
                     " is outside 1.." + std::to_string(max_size)};
    }
    RenderTarget t;
    t.width_ = width;
    t.height_ = height;
    t.colour_ = make_texture_2d(GL_SRGB8_ALPHA8, width, height, GL_LINEAR);
    t.depth_ = make_depth_renderbuffer(width, height);
    t.framebuffer_ = make_framebuffer_with(t.colour_.get(), t.depth_.get());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        return Error{"render target: framebuffer incomplete (status " + std::to_string(status) +
                     ")"};
    }
    auto ok = gl_check("render target");
    if (!ok) return Error{ok.error()};
    return t;
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, width_, height_);
}

Image RenderTarget::read() const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.get());
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width_) * height_ * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    // The exact inverse of the sRGB transfer function (IEC 61966-2-1), by table.
    float decode[256];
    for (int i = 0; i < 256; ++i) {
        const double c = i / 255.0;
        decode[i] =
            static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    Image image(width_, height_);
    for (int y = 0; y < height_; ++y) {
        const std::uint8_t* row =
            bytes.data() + static_cast<std::size_t>(height_ - 1 - y) * width_ * 4;
        for (int x = 0; x < width_; ++x) {
            const std::uint8_t* p = row + 4 * x;
            image.at(x, y) = {decode[p[0]], decode[p[1]], decode[p[2]], p[3] / 255.0f};
        }
    }
    return image;
}

}  // namespace gem::gpu
