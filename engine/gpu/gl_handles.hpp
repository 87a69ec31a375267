#pragma once
// Move-only owners of GL object names, deleted with the owner (the context must be current).

#include <utility>

#include <GLES3/gl3.h>

namespace gem::gpu {

template <void (*Delete)(GLuint)>
class GlHandle {
  public:
    GlHandle() = default;
    explicit GlHandle(GLuint name) : name_(name) {}
    GlHandle(GlHandle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    ~GlHandle() { reset(); }

    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset() {
        if (name_ != 0) Delete(name_);
        name_ = 0;
    }

  private:
    GLuint name_ = 0;
};

namespace detail {
inline void delete_texture(GLuint n) {
    glDeleteTextures(1, &n);
}
inline void delete_buffer(GLuint n) {
    glDeleteBuffers(1, &n);
}
inline void delete_framebuffer(GLuint n) {
    glDeleteFramebuffers(1, &n);
}
inline void delete_renderbuffer(GLuint n) {
    glDeleteRenderbuffers(1, &n);
}
inline void delete_vertex_array(GLuint n) {
    glDeleteVertexArrays(1, &n);
}
inline void delete_program(GLuint n) {
    glDeleteProgram(n);
}
inline void delete_query(GLuint n) {
    glDeleteQueries(1, &n);
}
inline void delete_sampler(GLuint n) {
    glDeleteSamplers(1, &n);
}
}  // namespace detail

using Texture = GlHandle<detail::delete_texture>;
using Buffer = GlHandle<detail::delete_buffer>;
using Framebuffer = GlHandle<detail::delete_framebuffer>;
using Renderbuffer = GlHandle<detail::delete_renderbuffer>;
using VertexArray = GlHandle<detail::delete_vertex_array>;
using ProgramHandle = GlHandle<detail::delete_program>;
using Sampler = GlHandle<detail::delete_sampler>;

inline Texture make_texture() {
    GLuint n = 0;
    glGenTextures(1, &n);
    return Texture(n);
}
// A width × height 2D texture of `format` (immutable storage, one level), sampled with
// `filter` and clamped at its edges; left bound to GL_TEXTURE_2D.
inline Texture make_texture_2d(GLenum format, int width, int height, GLenum filter) {
    Texture texture = make_texture();
    glBindTexture(GL_TEXTURE_2D, texture.get());
    glTexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}
// A sampler object reading with `filter` (level 0 only: no mip filter) and clamped at the edges,
// which overrides a texture's own filter while it is bound to the texture's unit.
inline Sampler make_sampler(GLenum filter) {
    GLuint n = 0;
    glGenSamplers(1, &n);
    glSamplerParameteri(n, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
    glSamplerParameteri(n, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
    glSamplerParameteri(n, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(n, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return Sampler(n);
}
inline Buffer make_buffer() {
    GLuint n = 0;
    glGenBuffers(1, &n);
    return Buffer(n);
}
inline Framebuffer make_framebuffer() {
    GLuint n = 0;
    glGenFramebuffers(1, &n);
    return Framebuffer(n);
}
inline Renderbuffer make_renderbuffer() {
    GLuint n = 0;
    glGenRenderbuffers(1, &n);
    return Renderbuffer(n);
}
// A 24-bit depth renderbuffer of width × height with an 8-bit stencil (the stones' visibility
// pass, frame_renderer.hpp; no more memory than depth alone where depth is kept in 32 bits),
// multisampled when `samples` > 1.
inline Renderbuffer make_depth_renderbuffer(int width, int height, int samples = 1) {
    Renderbuffer depth = make_renderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, depth.get());
    if (samples > 1) {
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width,
                                         height);
    } else {
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    }
    return depth;
}
// A framebuffer drawing into the 2D texture `colour` and, when given, the depth and stencil
// renderbuffer `depth`; left bound to GL_FRAMEBUFFER for the caller's completeness check.
inline Framebuffer make_framebuffer_with(GLuint colour, GLuint depth = 0) {
    Framebuffer framebuffer = make_framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
    if (depth != 0) {
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  depth);
    }
    return framebuffer;
}
inline VertexArray make_vertex_array() {
    GLuint n = 0;
    glGenVertexArrays(1, &n);
    return VertexArray(n);
}

}  // namespace gem::gpu
