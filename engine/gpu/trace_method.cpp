#include "gpu/trace_method.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cstdio>
#include <limits>
#include <optional>

#include "gpu/channel_wavelengths.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/render_target.hpp"
#include "render/camera.hpp"

namespace gem::gpu {
namespace {

// Texture units: the environment cube, then the stone's guess map or triangles.
constexpr int kEnvironmentUnit = 0;
constexpr int kStoneUnit = 1;

// trace.frag's STONE_EXIT_PLANES: one EXIT_PLANE(index, n.x, n.y, n.z, d) per facet, with
// nine significant digits (a float's round trip).
std::string exit_planes_define(const Stone& stone) {
    std::string text = "STONE_EXIT_PLANES";
    char one[160];
    for (std::size_t i = 0; i < stone.facets.size(); ++i) {
        const Plane& p = stone.facets[i].plane;
        std::snprintf(one, sizeof one, " EXIT_PLANE(%zu, %.9g, %.9g, %.9g, %.9g)", i, p.n.x, p.n.y,
                      p.n.z, p.d);
        text += one;
    }
    return text;
}

Result<Program> build_convex(const Stone& stone, ExitSearch search) {
    if (search == ExitSearch::constants) {
        return build_program("trace", {"EXIT_UNROLLED", exit_planes_define(stone)});
    }
    return build_program("trace");
}

}  // namespace

const char* to_string(ExitSearch search) {
    switch (search) {
        case ExitSearch::walk:
            return "facet walk";
        case ExitSearch::constants:
            return "every plane as constants";
        case ExitSearch::measured:
            return "measured";
    }
    return "?";
}

TraceMethod::TraceMethod(StoneGeometry geometry, Program program)
    : geometry_(std::move(geometry)), program_(std::move(program)) {}

Result<TraceMethod> TraceMethod::make(const Stone& stone, ExitSearch search) {
    auto geometry = StoneGeometry::upload(stone);
    if (!geometry) return Error{"trace: " + geometry.error()};
    const double radius = bounding_radius(stone.vertices);
    if (!stone.convex) {
        auto program = build_program("trace_non_convex");
        if (!program) return Error{program.error()};
        geometry.value().attach(program.value());
        return TraceMethod(std::move(geometry).value(), std::move(program).value());
    }
    if (search != ExitSearch::measured) {
        auto program = build_convex(stone, search);
        if (!program) return Error{program.error()};
        geometry.value().attach(program.value());
        TraceMethod m(std::move(geometry).value(), std::move(program).value());
        m.search_ = search;
        return m;
    }

    // Both variants on one small picture of the stone (a three-quarter view, the default trace
    // settings, an empty cube): the faster of three frames each, drawn to completion.
    auto walk = build_convex(stone, ExitSearch::walk);
    if (!walk) return Error{walk.error()};
    auto constants = build_convex(stone, ExitSearch::constants);
    if (!constants) return Error{constants.error()};
    constexpr int kSide = 64;
    auto target = RenderTarget::make(kSide, kSide);
    auto cube = EnvironmentCube::allocate(8);
    if (!target || !cube) return Error{!target ? target.error() : cube.error()};
    CameraSettings view;
    view.azimuth_deg = 10.0;
    view.elevation_deg = 40.0;
    auto camera = Camera::make(view, radius, kSide, kSide);
    if (!camera) return Error{"trace: " + camera.error()};
    GLint framebuffer = 0;
    GLint viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    target.value().bind();
    StoneFrame frame{&stone, stone.material, camera.value(), {}, &cube.value(), 0.0, 2.0 * radius};
    geometry.value().attach(walk.value());
    geometry.value().attach(constants.value());
    TraceMethod m(std::move(geometry).value(), std::move(walk).value());
    auto time_ms = [&]() -> Result<double> {
        double best = std::numeric_limits<double>::infinity();
        for (int i = 0; i < 3; ++i) {  // the first compiles the shader's last stages: not timed
            glDepthMask(GL_TRUE);
            glClearDepthf(1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            const auto start = std::chrono::steady_clock::now();
            auto ok = m.draw(frame, TraceSettings{});
            glFinish();
            if (!ok) return Error{ok.error()};
            const double ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            if (i > 0) best = std::min(best, ms);
        }
        return best;
    };
    auto walk_ms = time_ms();
    std::swap(m.program_, constants.value());
    auto constants_ms = walk_ms ? time_ms() : Result<double>(Error{""});
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    if (!walk_ms) return Error{walk_ms.error()};
    if (!constants_ms) return Error{constants_ms.error()};
    m.walk_ms_ = walk_ms.value();
    m.constants_ms_ = constants_ms.value();
    m.search_ = ExitSearch::constants;
    if (m.walk_ms_ <= m.constants_ms_) {
        std::swap(m.program_, constants.value());  // back to the walk
        m.search_ = ExitSearch::walk;
    }
    return m;
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
    const int mode = dispersion == TraceDispersion::none          ? 0
                     : dispersion == TraceDispersion::first_order ? 1
                                                                  : 2;
    program_.set("u_dispersion", mode);
    program_.set("u_ior_channel", channel_indices(frame.material));

    geometry_.draw_front_faces();
    return gl_check("trace pass");
}

}  // namespace gem::gpu
