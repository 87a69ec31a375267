#include "gpu/phong_method.hpp"

#include <cstdio>
#include <memory>
#include <vector>

#include "gpu/gl_check.hpp"
#include "gpu/stone_method.hpp"

namespace gem::gpu {

PhongMethod::PhongMethod(StoneGeometry geometry, ProgramVariants programs,
                         std::uint32_t specular_power)
    : geometry_(std::move(geometry)),
      programs_(std::move(programs)),
      specular_power_(specular_power) {}

Result<PhongMethod> PhongMethod::make(const Stone& stone, double h) {
    auto geometry = StoneGeometry::upload(stone);
    if (!geometry) return Error{"phong: " + geometry.error()};
    ProgramVariants programs("phong", {});
    const std::uint32_t power = specular_power_feature(h);
    auto built = programs.build_every_light_count(
        power, [&](const Program& p) { geometry.value().attach(p); });
    if (!built) return Error{built.error()};
    return PhongMethod(std::move(geometry).value(), std::move(programs), power);
}

Result<bool> PhongMethod::draw(const StoneFrame& frame) const {
    const Camera camera = stone_camera(frame);
    if (specular_power_feature(frame.shading.h) != specular_power_) {
        char h[32];
        std::snprintf(h, sizeof h, "%g", frame.shading.h);
        return Error{std::string("phong: drawn with a specular exponent of ") + h +
                     ", its programs were built for another"};
    }
    const Program& program =
        *programs_.find(light_count_feature(frame.shading.lights) | specular_power_);
    // The depth buffer holds what is drawn before the stone: the metal (frame_renderer.cpp
    // draws it first) and the piece's stones drawn before this one. Each step tests against
    // it, so a claw in front of the stone hides its facets.
    // 1. Back facets, seen through the front ones: blended, depth tested, not written.
    PipelineScope pass({&program, Blend::alpha, {true, GL_LESS, false}, Cull::front});
    program.set("u_view_projection", stone_view_projection(frame));
    const bool at_infinity = camera.orthographic();
    program.set("u_eye", at_infinity ? glm::vec3(-camera.forward())
                                     : glm::vec3(-camera.forward() * camera.distance()));
    program.set("u_eye_at_infinity", at_infinity ? 1 : 0);
    const SamplerBinding sharp = set_surface_uniforms(program, frame, 0);
    geometry_.bind_block();
    geometry_.draw_triangles();
    // 2. Front facets over them, keeping their depth.
    pass.change({&program, Blend::alpha, {true, GL_LESS, true}, Cull::back});
    geometry_.draw_triangles();
    return gl_check("phong pass");
}

namespace {

// The phong baseline as a stone method: one PhongMethod per kind of stone, drawn in order (a
// piece's stones are not sorted: where two overlap on screen the nearer one's front facets
// show, but a later stone's back facets are not blended under an earlier one's).
class PhongStones final : public StoneMethod {
  public:
    std::vector<std::unique_ptr<PhongMethod>> methods;

    Result<bool> draw(const std::vector<StoneFrame>& frames, const std::vector<std::size_t>& kinds,
                      FrameStats& stats) override {
        (void)stats;
        for (std::size_t i = 0; i < frames.size(); ++i) {
            auto ok = methods[kinds[i]]->draw(frames[i]);
            if (!ok) return ok;
        }
        return true;
    }
};

}  // namespace

Result<std::unique_ptr<StoneMethod>> make_phong_stones(const FrameSetup& setup,
                                                       const std::vector<const Stone*>& kinds) {
    auto method = std::make_unique<PhongStones>();
    for (const Stone* kind : kinds) {
        auto made = PhongMethod::make(*kind, setup.shading.h);
        if (!made) return Error{made.error()};
        method->methods.push_back(std::make_unique<PhongMethod>(std::move(made).value()));
    }
    return std::unique_ptr<StoneMethod>(std::move(method));
}

namespace {

std::vector<ProgramSpec> phong_programs() {
    // The alpha-blended Phong baseline, thesis fig. 8.17 (phong_method.hpp).
    return {{"phong",
             {"stone.vert"},
             {"stone.glsl", "specular.glsl", "phong.frag"},
             {},
             kLightCountBits | kSpecularPowerBits}};
}

std::vector<MethodRung> phong_rungs(const RungContext&) {
    return {{"phong", false, -1, "phong"}};
}

}  // namespace

extern const MethodEntry kPhongMethod;
constinit const MethodEntry kPhongMethod{.name = "phong",
                                         .needs_database = false,
                                         .draws_pieces = true,
                                         .refracts = false,
                                         .opacity_from_alpha = true,
                                         .make = make_phong_stones,
                                         .programs = phong_programs,
                                         .rungs = phong_rungs};

}  // namespace gem::gpu
