#include "gpu/visibility_target.hpp"

#include <GLES3/gl31.h>

#include "gpu/gl_extensions.hpp"

namespace gem::gpu {

int max_integer_samples() {
    GLint samples = 0;
    // Asked only of a context that knows the name: OpenGL ES 3.0 has none.
    if (gl_version_at_least(3, 1)) glGetIntegerv(GL_MAX_INTEGER_SAMPLES, &samples);
    return samples;
}

std::string multisampled_visibility_note(int max_integer_samples) {
    if (max_integer_samples >= 2) return {};
    return "a multisampled frame's stones are shaded facet by facet: this GL has no "
           "multisampled integer texture (OpenGL ES 3.1) for their visibility pass";
}

VisibilityTarget::VisibilityTarget(int max_integer_samples)
    : max_integer_samples_(max_integer_samples >= 2 ? max_integer_samples : 0) {}

VisibilityAttachment VisibilityTarget::attach(glm::ivec2 size, int samples) {
    GLint framebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    if (framebuffer == 0) return {};
    if (samples > 0 && (samples > max_integer_samples_ || samples > kMaxSamples)) return {};
    const GLenum target = samples > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
    if (!texture_ || size_ != size || samples_ != samples) {
        if (samples > 0) {
            texture_ = make_texture();
            glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, texture_.get());
            // Fixed sample locations: the framebuffer's other attachments are renderbuffers.
            glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, GL_RG16UI, size.x, size.y,
                                      GL_TRUE);
            glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
        } else {
            texture_ = make_texture_2d(GL_RG16UI, size.x, size.y, GL_NEAREST);
        }
        size_ = size;
        samples_ = samples;
    }
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, target, texture_.get(), 0);
    if (glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, target, 0, 0);
        return {};
    }
    return {texture_.get(), samples};
}

void VisibilityTarget::detach() const {
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT1,
                           samples_ > 0 ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D, 0, 0);
}

}  // namespace gem::gpu
