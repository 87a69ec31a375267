#pragma once
// The GL state a pass draws with, stated as one value (as sokol's pipeline objects are) and
// applied in one place. Between passes the GL is at rest: GL's initial state, no program in
// use and no vertex array bound. A pass moves it from rest to its pipeline for its scope and
// back (PipelineScope), changing only what differs, so no pass reads or leaves another's state.
//
// Not a pass's: the framebuffer, viewport and scissor belong to whoever binds the target (a
// still frame's band is scissored about every pass drawn into it); the colour attachments a
// frame writes are its framebuffer's (glDrawBuffers); textures and uniforms are set by each
// pass after its pipeline is applied.

#include <cstdint>
#include <string>

#include <GLES3/gl3.h>

namespace gem::gpu {

class Program;

enum class Blend : std::uint8_t {
    off,
    alpha,           // GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA: over what is drawn
    constant_alpha,  // GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA: glBlendColor's alpha
};

enum class Cull : std::uint8_t { off, back, front };  // counter-clockwise faces are front

struct DepthState {
    constexpr DepthState(bool test_ = false, GLenum func_ = GL_LESS, bool write_ = true,
                         bool at_far_plane_ = false)
        : test(test_), func(func_), write(write_), at_far_plane(at_far_plane_) {}
    bool test;
    GLenum func;
    bool write;
    // glDepthRangef(1, 1): every fragment written at the far plane (phong's forgetting pass).
    bool at_far_plane;
    bool operator==(const DepthState&) const = default;
};

// The stencil as the passes use it: one reference, every bit read and written; a failing
// stencil or depth test keeps the value.
struct StencilState {
    constexpr StencilState(bool test_ = false, GLenum func_ = GL_ALWAYS, GLint ref_ = 0,
                           GLenum pass_op_ = GL_KEEP)
        : test(test_), func(func_), ref(ref_), pass_op(pass_op_) {}
    bool test;
    GLenum func;
    GLint ref;
    GLenum pass_op;  // where stencil and depth pass
    bool operator==(const StencilState&) const = default;
};

// A program drawn with the rest at GL's initial state unless stated: no blending, no depth
// test, no culling, colour written, no stencil test.
struct Pipeline {
    constexpr Pipeline(const Program* program_ = nullptr, Blend blend_ = Blend::off,
                       DepthState depth_ = {}, Cull cull_ = Cull::off)
        : program(program_), blend(blend_), depth(depth_), cull(cull_) {}
    const Program* program;
    Blend blend;
    DepthState depth;
    Cull cull;
    bool colour_write = true;
    StencilState stencil;
    bool operator==(const Pipeline&) const = default;
};

// The GL at rest: its initial state (OpenGL ES 3.0 §2.13 and chapter 4's tables).
inline constexpr Pipeline kAtRest{};

// Changes the GL from `from` to `to`, touching only the state that differs.
void change_pipeline(const Pipeline& from, const Pipeline& to);

// A pass's pipeline, applied from rest for the scope and back to rest however the pass ends
// (the vertex array too, which each draw binds).
class PipelineScope {
  public:
    explicit PipelineScope(const Pipeline& pipeline);
    ~PipelineScope();
    // A pass of several steps (a depth pass, then the shading) moves between its pipelines.
    void change(const Pipeline& pipeline);
    PipelineScope(const PipelineScope&) = delete;
    PipelineScope& operator=(const PipelineScope&) = delete;

  private:
    Pipeline current_;
};

// What of the pipeline state the GL reports away from rest, one "name=value" each, for a test
// that a pass left nothing behind; empty at rest.
std::string state_left_behind();

}  // namespace gem::gpu
