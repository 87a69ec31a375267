#pragma once
// Restores the draw framebuffer and viewport a pass found bound, however the pass ends: for
// passes that draw off screen (the ring's cube faces, a stone measured alone, the trace's test
// picture) on behalf of a caller who has its own target bound.

#include <GLES3/gl3.h>

namespace gem::gpu {

class FramebufferScope {
  public:
    FramebufferScope() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
    }
    ~FramebufferScope() {
        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    }
    FramebufferScope(const FramebufferScope&) = delete;
    FramebufferScope& operator=(const FramebufferScope&) = delete;

  private:
    GLint framebuffer_ = 0;
    GLint viewport_[4] = {};
};

}  // namespace gem::gpu
