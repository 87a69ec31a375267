#include "gpu/trace_method.hpp"

#include <cassert>

#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"

namespace gem::gpu {
namespace {

// Texture units: the environment cube, then the planes and triangles (StoneTextures::bind).
constexpr int kEnvironmentUnit = 0;
constexpr int kStoneUnit = 1;

}  // namespace

TraceMethod::TraceMethod(StoneTextures textures, Program program)
    : textures_(std::move(textures)), program_(std::move(program)), empty_(make_vertex_array()) {}

Result<TraceMethod> TraceMethod::make(const Stone& stone) {
    auto textures = StoneTextures::upload(stone);
    if (!textures) return Error{textures.error()};
    auto program = build_program(stone.convex ? "trace" : "trace_non_convex");
    if (!program) return Error{program.error()};
    return TraceMethod(std::move(textures).value(), std::move(program).value());
}

Result<bool> TraceMethod::draw(const StoneFrame& frame, const TraceSettings& trace) {
    assert(frame.environment != nullptr);
    program_.use();
    set_camera_uniforms(program_, frame.camera, frame.scene_radius_mm);
    set_shading_uniforms(program_, frame, kEnvironmentUnit);
    textures_.bind(program_, kStoneUnit);
    program_.set("u_ior", static_cast<float>(frame.material.index()));
    program_.set("u_max_depth", trace.max_depth);
    program_.set("u_min_weight", static_cast<float>(trace.min_weight));
    program_.set("u_thesis_weights", trace.weights == WeightModel::thesis_factors ? 1 : 0);
    program_.set("u_r_factor", static_cast<float>(trace.r_factor));
    program_.set("u_t_factor", static_cast<float>(trace.t_factor));

    draw_stone_pass(empty_);
    return gl_check("trace pass");
}

}  // namespace gem::gpu
