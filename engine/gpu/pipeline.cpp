#include "gpu/pipeline.hpp"

#include "gpu/program.hpp"

namespace gem::gpu {
namespace {

void set_enabled(GLenum capability, bool on) {
    on ? glEnable(capability) : glDisable(capability);
}

void change_blend(Blend from, Blend to) {
    if (from == to) return;
    if ((from == Blend::off) != (to == Blend::off)) set_enabled(GL_BLEND, to != Blend::off);
    // GL's initial factors are (GL_ONE, GL_ZERO); a pass that blends sets its own, and they
    // return to GL's when blending goes off, so that rest is GL's initial state.
    switch (to) {
        case Blend::off:
            glBlendFunc(GL_ONE, GL_ZERO);
            break;
        case Blend::alpha:
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            break;
        case Blend::constant_alpha:
            glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
            break;
    }
}

void change_depth(const DepthState& from, const DepthState& to) {
    if (from.test != to.test) set_enabled(GL_DEPTH_TEST, to.test);
    if (from.func != to.func) glDepthFunc(to.func);
    if (from.write != to.write) glDepthMask(to.write ? GL_TRUE : GL_FALSE);
    if (from.at_far_plane != to.at_far_plane) {
        to.at_far_plane ? glDepthRangef(1.0f, 1.0f) : glDepthRangef(0.0f, 1.0f);
    }
}

void change_cull(Cull from, Cull to) {
    if (from == to) return;
    if ((from == Cull::off) != (to == Cull::off)) set_enabled(GL_CULL_FACE, to != Cull::off);
    const GLenum face_from = from == Cull::front ? GL_FRONT : GL_BACK;
    const GLenum face_to = to == Cull::front ? GL_FRONT : GL_BACK;
    if (face_from != face_to) glCullFace(face_to);
}

void change_stencil(const StencilState& from, const StencilState& to) {
    if (from.test != to.test) set_enabled(GL_STENCIL_TEST, to.test);
    if (from.func != to.func || from.ref != to.ref) glStencilFunc(to.func, to.ref, 0xff);
    if (from.pass_op != to.pass_op) glStencilOp(GL_KEEP, GL_KEEP, to.pass_op);
}

}  // namespace

void change_pipeline(const Pipeline& from, const Pipeline& to) {
    if (from.program != to.program) glUseProgram(to.program ? to.program->id() : 0);
    change_blend(from.blend, to.blend);
    change_depth(from.depth, to.depth);
    change_cull(from.cull, to.cull);
    if (from.colour_write != to.colour_write) {
        const GLboolean on = to.colour_write ? GL_TRUE : GL_FALSE;
        glColorMask(on, on, on, on);
    }
    change_stencil(from.stencil, to.stencil);
}

PipelineScope::PipelineScope(const Pipeline& pipeline) : current_(pipeline) {
    change_pipeline(kAtRest, pipeline);
}

PipelineScope::~PipelineScope() {
    glBindVertexArray(0);
    change_pipeline(current_, kAtRest);
}

void PipelineScope::change(const Pipeline& pipeline) {
    change_pipeline(current_, pipeline);
    current_ = pipeline;
}

std::string state_left_behind() {
    std::string out;
    const auto away = [&out](const char* name, GLint value, GLint at_rest) {
        if (value == at_rest) return;
        out += (out.empty() ? "" : " ") + std::string(name) + "=" + std::to_string(value);
    };
    const auto integer = [](GLenum what) {
        GLint v = 0;
        glGetIntegerv(what, &v);
        return v;
    };
    GLint colour_mask[4] = {};
    glGetIntegerv(GL_COLOR_WRITEMASK, colour_mask);
    GLfloat depth_range[2] = {};
    glGetFloatv(GL_DEPTH_RANGE, depth_range);
    away("program", integer(GL_CURRENT_PROGRAM), 0);
    away("vertex_array", integer(GL_VERTEX_ARRAY_BINDING), 0);
    away("blend", glIsEnabled(GL_BLEND), GL_FALSE);
    away("blend_src", integer(GL_BLEND_SRC_RGB), GL_ONE);
    away("blend_dst", integer(GL_BLEND_DST_RGB), GL_ZERO);
    away("depth_test", glIsEnabled(GL_DEPTH_TEST), GL_FALSE);
    away("depth_func", integer(GL_DEPTH_FUNC), GL_LESS);
    away("depth_write", integer(GL_DEPTH_WRITEMASK), GL_TRUE);
    away("depth_range_near", depth_range[0] == 0.0f ? 0 : 1, 0);
    away("depth_range_far", depth_range[1] == 1.0f ? 1 : 0, 1);
    away("cull", glIsEnabled(GL_CULL_FACE), GL_FALSE);
    away("cull_face", integer(GL_CULL_FACE_MODE), GL_BACK);
    away("front_face", integer(GL_FRONT_FACE), GL_CCW);
    for (int i = 0; i < 4; ++i) away("colour_write", colour_mask[i], GL_TRUE);
    away("stencil_test", glIsEnabled(GL_STENCIL_TEST), GL_FALSE);
    away("stencil_func", integer(GL_STENCIL_FUNC), GL_ALWAYS);
    away("stencil_ref", integer(GL_STENCIL_REF), 0);
    away("stencil_pass", integer(GL_STENCIL_PASS_DEPTH_PASS), GL_KEEP);
    away("stencil_fail", integer(GL_STENCIL_FAIL), GL_KEEP);
    away("stencil_depth_fail", integer(GL_STENCIL_PASS_DEPTH_FAIL), GL_KEEP);
    away("stencil_write", integer(GL_STENCIL_WRITEMASK) & 0xff, 0xff);
    away("scissor", glIsEnabled(GL_SCISSOR_TEST), GL_FALSE);
    return out;
}

}  // namespace gem::gpu
