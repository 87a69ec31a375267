#pragma once
// The stones' visibility target (FrameRenderer::render): each pixel's, or in a multisampled
// frame each sample's, entry facet and stone (RG16UI), written by the stones' depth pass
// (stone_visibility.frag) and read by their shading pass (trace.frag, VISIBILITY). A
// multisampled frame needs a multisampled integer texture, which OpenGL ES 3.1 added; where the
// GL lacks it, such frames' stones are drawn facet by facet (multisampled_visibility_note()).

#include <string>

#include <GLES3/gl3.h>
#include <glm/glm.hpp>

#include "gpu/gl_handles.hpp"

namespace gem::gpu {

// The most samples the current context holds in an integer texture: 0 in OpenGL ES 3.0, which
// has no multisampled integer texture.
int max_integer_samples();
// Why a multisampled frame's stones are shaded facet by facet on a GL holding at most
// `max_integer_samples` in an integer texture; empty where they need not be. A property of the
// GL: said once, where the display opens.
std::string multisampled_visibility_note(int max_integer_samples);

struct VisibilityAttachment {
    GLuint texture = 0;  // 0: not attached, the stones drawn facet by facet
    int samples = 0;     // 0: one sample a pixel (a 2D texture), else a 2D multisample texture
};

class VisibilityTarget {
  public:
    // The most samples a multisampled frame's shading pass reads (trace.frag's kMaxSamples).
    static constexpr int kMaxSamples = 8;

    // `max_integer_samples`: the most samples an integer texture may hold; 0 where it may not
    // be multisampled (the current context's by default).
    explicit VisibilityTarget(int max_integer_samples = gpu::max_integer_samples());

    // Attached as the bound draw framebuffer's second colour attachment, sized as that
    // framebuffer and with its `samples` (GL_SAMPLES; the default framebuffer takes none). Not
    // cleared here: a multisampled one is cleared about each stone by its method
    // (TraceMethod::clear_visibility), a single-sample one is read only where the stencil says the
    // pass wrote it this frame.
    VisibilityAttachment attach(glm::ivec2 size, int samples);
    // Takes it off the bound draw framebuffer again (before the stones' pass reads it).
    void detach() const;

  private:
    Texture texture_;
    glm::ivec2 size_{0};
    int samples_ = -1;             // what texture_ was made with
    int max_integer_samples_ = 0;  // 0: no multisampled integer texture
};

}  // namespace gem::gpu
