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

ProgramVariants convex_programs(const Stone& stone, ExitSearch search) {
    if (search == ExitSearch::constants) {
        return ProgramVariants("trace", {"EXIT_UNROLLED", exit_planes_define(stone)});
    }
    return ProgramVariants("trace", {});
}

std::uint32_t fire_features(TraceDispersion dispersion) {
    switch (dispersion) {
        case TraceDispersion::none:
            return 0;
        case TraceDispersion::first_order:
            return kFireFirstOrder;
        case TraceDispersion::exact:
            return kFireExact;
    }
    return 0;
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

TraceMethod::TraceMethod(StoneGeometry geometry, ProgramVariants programs, bool convex)
    : geometry_(std::move(geometry)), programs_(std::move(programs)), convex_(convex) {}

Result<const Program*> TraceMethod::program(std::uint32_t features) {
    return programs_.get(features, [&](const Program& built) { geometry_.attach(built); });
}

Result<TraceMethod> TraceMethod::make(const Stone& stone, ExitSearch search) {
    auto geometry = StoneGeometry::upload(stone);
    if (!geometry) return Error{"trace: " + geometry.error()};
    const double radius = bounding_radius(stone.vertices);
    if (!stone.convex) {
        return TraceMethod(std::move(geometry).value(), ProgramVariants("trace_non_convex", {}),
                           false);
    }
    if (search != ExitSearch::measured) {
        TraceMethod m(std::move(geometry).value(), convex_programs(stone, search), true);
        m.search_ = search;
        return m;
    }

    // Both searches on one small picture of the stone (a three-quarter view, the default trace
    // settings, an empty cube): the faster of three frames each, drawn to completion.
    ProgramVariants constants = convex_programs(stone, ExitSearch::constants);
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
    TraceMethod m(std::move(geometry).value(), convex_programs(stone, ExitSearch::walk), true);
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
    std::swap(m.programs_, constants);
    auto constants_ms = walk_ms ? time_ms() : Result<double>(Error{""});
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    if (!walk_ms) return Error{walk_ms.error()};
    if (!constants_ms) return Error{constants_ms.error()};
    m.walk_ms_ = walk_ms.value();
    m.constants_ms_ = constants_ms.value();
    m.search_ = ExitSearch::constants;
    if (m.walk_ms_ <= m.constants_ms_) {
        std::swap(m.programs_, constants);  // back to the walk
        m.search_ = ExitSearch::walk;
    }
    return m;
}

Result<bool> TraceMethod::draw(const StoneFrame& frame, const TraceSettings& trace,
                               TraceDispersion dispersion) {
    assert(frame.environment != nullptr);
    // A non-convex stone's branches are traced at one index (trace.frag).
    const std::uint32_t features =
        shading_features(frame) | (convex_ ? fire_features(dispersion) : 0u);
    auto chosen = program(features);
    if (!chosen) return Error{chosen.error()};
    const Program& p = *chosen.value();
    p.use();
    set_camera_uniforms(p, frame.camera, frame.scene_radius_mm);
    set_shading_uniforms(p, frame, kEnvironmentUnit);
    geometry_.bind(p, kStoneUnit);
    p.set("u_facet_count", geometry_.facet_count());
    p.set("u_ior", static_cast<float>(frame.material.index()));
    p.set("u_max_depth", trace.max_depth);
    p.set("u_min_weight", static_cast<float>(trace.min_weight));
    p.set("u_thesis_weights", trace.weights == WeightModel::thesis_factors ? 1 : 0);
    p.set("u_r_factor", static_cast<float>(trace.r_factor));
    p.set("u_t_factor", static_cast<float>(trace.t_factor));
    p.set("u_ior_channel", channel_indices(frame.material));

    geometry_.draw_front_faces();
    return gl_check("trace pass");
}

}  // namespace gem::gpu
