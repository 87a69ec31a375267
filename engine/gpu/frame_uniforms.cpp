#include "gpu/frame_uniforms.hpp"

#include <algorithm>

#include "gpu/ring_renderer.hpp"

namespace gem::gpu {

glm::mat4 view_projection(const Camera& camera, double scene_radius_mm) {
    const glm::dvec3 f = camera.forward();
    const glm::dvec3 r = camera.right();
    const glm::dvec3 u = camera.up();
    const double half_w = 0.5 * camera.width() * camera.pixel_size();
    const double half_h = 0.5 * camera.height() * camera.pixel_size();
    const double radius = scene_radius_mm;
    glm::dmat4 m(0.0);  // column-major: m[column][row]
    if (camera.orthographic()) {
        // ndc = (p·r / half_w, p·u / half_h, p·f / radius)
        for (int i = 0; i < 3; ++i) {
            m[i][0] = r[i] / half_w;
            m[i][1] = u[i] / half_h;
            m[i][2] = f[i] / radius;
        }
        m[3][3] = 1.0;
    } else {
        // Eye at -f·D; view depth z = D + p·f; x_ndc = (p·r) / (z half_w) with half_w in
        // tangent units; depth maps z = D − R .. D + R onto −1..1 as a GL perspective does.
        const double dist = camera.distance();
        const double n = std::max(dist - radius, 1e-3 * dist);
        const double fa = dist + radius;
        for (int i = 0; i < 3; ++i) {
            m[i][0] = r[i] / half_w;
            m[i][1] = u[i] / half_h;
            m[i][2] = f[i] * (fa + n) / (fa - n);
            m[i][3] = f[i];
        }
        m[3][2] = dist * (fa + n) / (fa - n) - 2.0 * fa * n / (fa - n);
        m[3][3] = dist;
    }
    // The framing shift moves the picture: ndc += shift, i.e. clip x, y += shift times w.
    for (int column = 0; column < 4; ++column) {
        m[column][0] += camera.shift().x * m[column][3];
        m[column][1] += camera.shift().y * m[column][3];
    }
    return glm::mat4(m);
}

void set_ray_uniforms(const Program& program, const Camera& camera) {
    program.set("u_cam_forward", glm::vec3(camera.forward()));
    program.set("u_cam_right", glm::vec3(camera.right()));
    program.set("u_cam_up", glm::vec3(camera.up()));
    program.set("u_cam_half", glm::vec2(0.5 * camera.width() * camera.pixel_size(),
                                        0.5 * camera.height() * camera.pixel_size()));
    program.set("u_cam_shift", glm::vec2(camera.shift()));
    program.set("u_cam_distance", static_cast<float>(camera.distance()));
    program.set("u_cam_start", static_cast<float>(camera.ray_start()));
    program.set("u_viewport_px", glm::vec2(camera.width(), camera.height()));
}

Camera stone_camera(const StoneFrame& frame) {
    return frame.camera.in_frame(frame.placement.rotation, frame.placement.position);
}

glm::mat4 stone_view_projection(const StoneFrame& frame) {
    glm::dmat4 model(frame.placement.rotation);
    model[3] = glm::dvec4(frame.placement.position, 1.0);
    return glm::mat4(glm::dmat4(view_projection(frame.camera, frame.scene_radius_mm)) * model);
}

void set_camera_uniforms(const Program& program, const StoneFrame& frame) {
    set_ray_uniforms(program, stone_camera(frame));
    program.set("u_view_projection", stone_view_projection(frame));
}

std::uint32_t shading_features(const StoneFrame& frame) {
    std::uint32_t features = 0;
    if (frame.shading.model == ShadingModel::thesis) features |= kThesisShading;
    if (frame.cube_half_mm <= 0.0) features |= kCubeAtInfinity;
    // A colourless stone skips an exp(0) per exit (about a tenth of a diamond's trace frame on
    // llvmpipe).
    const glm::dvec3 sigma = frame.material.absorption_per_mm;
    if (frame.shading.model == ShadingModel::physical &&
        (sigma.x > 0.0 || sigma.y > 0.0 || sigma.z > 0.0)) {
        features |= kAbsorbing;
    }
    // A piece's exits are followed under the physical shading only: the thesis' is no light
    // transport to correct.
    if (frame.piece_sight != nullptr && frame.shading.model == ShadingModel::physical) {
        features |= kSeesPiece;
    }
    return features | light_count_feature(frame.shading.lights) |
           specular_power_feature(frame.shading.h);
}

void set_piece_sight_uniforms(const Program& program, const StoneFrame& frame, int first_unit) {
    if ((shading_features(frame) & kSeesPiece) == 0) return;
    frame.piece_sight->set_piece_sight_uniforms(program, frame.shading, frame.still.index,
                                                first_unit);
}

namespace {

void set_lights(const Program& program, const std::vector<Light>& lights,
                const Placement& placement, const char* position_name, const char* colour_name) {
    glm::vec4 position[kMaxLights] = {};
    glm::vec3 colour[kMaxLights] = {};
    const int count = light_count_of(light_count_feature(lights));
    for (int i = 0; i < count; ++i) {
        const Light& l = lights[static_cast<std::size_t>(i)];
        position[i] = l.directional
                          ? glm::vec4(glm::vec3(placement.direction_to_stone(l.position)), 0.0f)
                          : glm::vec4(glm::vec3(placement.to_stone(l.position)), 1.0f);
        colour[i] = glm::vec3(l.colour);
    }
    glUniform4fv(program.uniform(position_name), kMaxLights, &position[0].x);
    glUniform3fv(program.uniform(colour_name), kMaxLights, &colour[0].x);
}

}  // namespace

void set_light_uniforms(const Program& program, const std::vector<Light>& lights,
                        const Placement& placement) {
    set_lights(program, lights, placement, "u_light_position", "u_light_colour");
}

void set_piece_light_uniforms(const Program& program, const std::vector<Light>& lights) {
    set_lights(program, lights, {}, "u_piece_light_position", "u_piece_light_colour");
}

SamplerBinding::SamplerBinding(GLuint unit, GLuint sampler) : unit_(unit) {
    glBindSampler(unit, sampler);
}

SamplerBinding::~SamplerBinding() {
    glBindSampler(unit_, 0);
}

SamplerBinding set_surface_uniforms(const Program& program, const StoneFrame& frame, int unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, frame.environment->texture());
    program.set("u_environment", unit);
    program.set("u_frame_rotation", glm::mat3(frame.placement.rotation));
    const ShadingSettings& s = frame.shading;
    set_light_uniforms(program, s.lights, frame.placement);
    program.set("u_k_s", static_cast<float>(s.k_s));
    program.set("u_h", static_cast<float>(s.h));
    program.set("u_alpha", static_cast<float>(s.alpha));
    program.set("u_stone_colour", glm::vec3(frame.material.body_colour));
    return SamplerBinding(static_cast<GLuint>(unit), frame.environment->sharp_sampler());
}

SamplerBinding set_shading_uniforms(const Program& program, const StoneFrame& frame, int unit) {
    program.set("u_cube_half_mm", static_cast<float>(frame.cube_half_mm));
    program.set("u_frame_origin", glm::vec3(frame.placement.position));
    program.set("u_k_st", static_cast<float>(frame.shading.k_st));
    program.set("u_absorption", glm::vec3(frame.material.absorption_per_mm));
    return set_surface_uniforms(program, frame, unit);
}

}  // namespace gem::gpu
