#pragma once
// The stones' visibility target (FrameRenderer::render): each pixel's, or in a multisampled
// frame each sample's, entry facet and stone (RG16UI), written by the stones' depth pass
// (stone_visibility.frag) and read by their shading pass (trace.frag, VISIBILITY). A
// multisampled frame needs a multisampled integer texture, which OpenGL ES 3.1 added; where the
// GL lacks it, such frames' stones are drawn facet by facet, and note() says why.

#include <string>

#include <GLES3/gl3.h>
#include <glm/glm.hpp>

#include "gpu/gl_handles.hpp"

namespace gem::gpu {

// The most samples the current context holds in an integer texture: 0 in OpenGL ES 3.0, which
// has no multisampled integer texture.
int max_integer_samples();

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

    // Attached as the bound draw framebuffer's second colour attachment, sized and sampled as
    // that framebuffer (the default framebuffer takes none). Not cleared here: a multisampled
    // one is cleared about each stone by its method (TraceMethod::clear_visibility), a
    // single-sample one is read only where the stencil says the pass wrote it this frame.
    VisibilityAttachment attach(glm::ivec2 size);
    // Takes it off the bound draw framebuffer again (before the stones' pass reads it).
    void detach() const;

    // Why a multisampled frame's stones are drawn facet by facet; empty where they are not.
    const std::string& note() const { return note_; }

  private:
    Texture texture_;
    glm::ivec2 size_{0};
    int samples_ = -1;             // what texture_ was made with
    int max_integer_samples_ = 0;  // 0: no multisampled integer texture
    std::string note_;
};

}  // namespace gem::gpu
