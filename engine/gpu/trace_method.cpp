#include "gpu/trace_method.hpp"

#include <cassert>

#include "gpu/channel_wavelengths.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"
#include "render/camera.hpp"

namespace gem::gpu {
namespace {

// Texture units: the environment cube, then the stone's guess map or triangles.
constexpr int kEnvironmentUnit = 0;
constexpr int kStoneUnit = 1;

}  // namespace

TraceMethod::TraceMethod(StoneGeometry geometry, Program program, double radius_mm)
    : geometry_(std::move(geometry)), program_(std::move(program)), radius_mm_(radius_mm) {}

Result<TraceMethod> TraceMethod::make(const Stone& stone) {
    auto geometry = StoneGeometry::upload(stone);
    if (!geometry) return Error{"trace: " + geometry.error()};
    auto program = build_program(stone.convex ? "trace" : "trace_non_convex");
    if (!program) return Error{program.error()};
    geometry.value().attach(program.value());
    return TraceMethod(std::move(geometry).value(), std::move(program).value(),
                       bounding_radius(stone.vertices));
}

Result<bool> TraceMethod::draw(const StoneFrame& frame, const TraceSettings& trace,
                               TraceDispersion dispersion) {
    assert(frame.environment != nullptr);
    program_.use();
    set_camera_uniforms(program_, frame.camera, frame.scene_radius_mm);
    set_shading_uniforms(program_, frame, kEnvironmentUnit);
    geometry_.bind(program_, kStoneUnit);
    program_.set("u_facet_count", geometry_.facet_count());
    program_.set("u_ior", static_cast<float>(frame.material.index()));
    program_.set("u_max_depth", trace.max_depth);
    program_.set("u_min_weight", static_cast<float>(trace.min_weight));
    program_.set("u_thesis_weights", trace.weights == WeightModel::thesis_factors ? 1 : 0);
    program_.set("u_r_factor", static_cast<float>(trace.r_factor));
    program_.set("u_t_factor", static_cast<float>(trace.t_factor));
    // Float rounding of plane values at points a stone's radius from its centre is ~1e-7 of
    // the radius; ten times that is still far below a pixel.
    program_.set("u_walk_slack", static_cast<float>(1e-6 * radius_mm_));
    const int mode = dispersion == TraceDispersion::none          ? 0
                     : dispersion == TraceDispersion::first_order ? 1
                                                                  : 2;
    program_.set("u_dispersion", mode);
    program_.set("u_ior_channel", channel_indices(frame.material));

    geometry_.draw_front_faces();
    return gl_check("trace pass");
}

}  // namespace gem::gpu
