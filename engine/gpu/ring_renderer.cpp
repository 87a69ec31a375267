#include "gpu/ring_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/frame_uniforms.hpp"
#include "gpu/framebuffer_scope.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/visibility_target.hpp"
#include "optics/microfacet.hpp"
#include "scene/lights.hpp"

namespace gem::gpu {
namespace {

Buffer upload(GLenum target, const void* data, std::size_t bytes) {
    Buffer buffer = make_buffer();
    glBindBuffer(target, buffer.get());
    glBufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
    return buffer;
}

}  // namespace

glm::mat4 cube_face_projection(int face, double near_mm, double far_mm) {
    const CubeFaceBasis basis = cube_face_basis(face);
    const double a = (far_mm + near_mm) / (far_mm - near_mm);
    const double b = -2.0 * far_mm * near_mm / (far_mm - near_mm);
    glm::dmat4 m(0.0);  // column-major: m[column][row]
    for (int i = 0; i < 3; ++i) {
        m[i][0] = basis.right[i];
        m[i][1] = basis.up[i];
        m[i][2] = basis.forward[i] * a;
        m[i][3] = basis.forward[i];
    }
    m[3][2] = b;
    return glm::mat4(m);
}

RingRenderer::RingRenderer(ProgramVariants ring, Program depth, Program background,
                           MetalEnvironment environment)
    : ring_(std::move(ring)),
      depth_(std::move(depth)),
      background_(std::move(background)),
      environment_(std::move(environment)) {}

Result<RingRenderer> RingRenderer::make(const MetalMesh& mesh, const EnvironmentCube& environment) {
    if (mesh.positions.size() != mesh.normals.size() || mesh.indices.size() % 3 != 0) {
        return Error{"ring renderer: the mesh has " + std::to_string(mesh.positions.size()) +
                     " positions, " + std::to_string(mesh.normals.size()) + " normals and " +
                     std::to_string(mesh.indices.size()) + " indices (not whole triangles)"};
    }
    for (std::uint32_t i : mesh.indices) {
        if (i >= mesh.positions.size()) {
            return Error{"ring renderer: index " + std::to_string(i) + " past the " +
                         std::to_string(mesh.positions.size()) + " vertices"};
        }
    }
    // Every light count up front: draws are const and must not build. Where a multisampled
    // frame's stones may go by visibility (VisibilityTarget), each again marking the samples it
    // takes from them.
    ProgramVariants ring("ring", {});
    auto built = ring.build_every_light_count(0, [](const Program&) {});
    if (built && max_integer_samples() >= 2) {
        built = ring.build_every_light_count(kVisibility, [](const Program&) {});
    }
    if (!built) return Error{built.error()};
    auto depth = build_program("ring_depth");
    if (!depth) return Error{depth.error()};
    auto background = build_program("background");
    if (!background) return Error{background.error()};
    auto metal_environment = MetalEnvironment::make(environment, mesh.roughness);
    if (!metal_environment) return Error{"ring renderer: " + metal_environment.error()};
    RingRenderer r(std::move(ring), std::move(depth).value(), std::move(background).value(),
                   std::move(metal_environment).value());
    r.f0_ = mesh.f0;
    r.roughness_ = std::clamp(mesh.roughness, 0.0f, 1.0f);
    r.radius_mm_ = mesh.radius_mm();
    r.closed_ = mesh.closed;
    r.index_count_ = static_cast<GLsizei>(mesh.indices.size());
    r.vertex_array_ = make_vertex_array();
    glBindVertexArray(r.vertex_array_.get());
    if (r.index_count_ > 0) {
        r.positions_ = upload(GL_ARRAY_BUFFER, mesh.positions.data(),
                              mesh.positions.size() * sizeof(glm::vec3));
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        glEnableVertexAttribArray(0);
        r.normals_ =
            upload(GL_ARRAY_BUFFER, mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        glEnableVertexAttribArray(1);
        // The element buffer binding is part of the vertex array's state.
        r.indices_ = upload(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.data(),
                            mesh.indices.size() * sizeof(std::uint32_t));
    }
    glBindVertexArray(0);
    auto ok = gl_check("ring renderer: upload");
    if (!ok) return Error{ok.error()};
    return r;
}

Result<bool> RingRenderer::see_piece(PieceSight sight, const glm::vec3& environment_mean) {
    environment_mean_ = (environment_mean.x + environment_mean.y + environment_mean.z) / 3.0f;
    ProgramVariants ring("ring", {});
    auto built = ring.build_every_light_count(kSeesPiece, [](const Program&) {});
    if (!built) return Error{built.error()};
    ring_sees_piece_ = std::move(ring);
    sight_ = std::move(sight);
    return true;
}

void RingRenderer::set_metal_uniforms(const Program& program, const ShadingSettings& lights,
                                      int first_unit) const {
    program.set("u_metal_f0", f0_);
    // Constant over the mesh: the alphas of metal.glsl's lobes and a light lobe's solid angle.
    const double alpha = ggx_alpha(roughness_);
    program.set("u_metal_roughness", roughness_);
    program.set("u_metal_alpha", static_cast<float>(alpha));
    program.set("u_metal_alpha_lit", static_cast<float>(std::sqrt(alpha * alpha + 1.0 / lights.h)));
    program.set("u_lobe_solid_angle",
                static_cast<float>(2.0 * 3.14159265358979323846 / (lights.h + 1.0)));
    glActiveTexture(GL_TEXTURE0 + first_unit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, environment_.filtered().texture());
    program.set("u_metal_environment", first_unit);
    glActiveTexture(GL_TEXTURE0 + first_unit + 1);
    glBindTexture(GL_TEXTURE_2D, environment_.brdf_table());
    program.set("u_environment_brdf", first_unit + 1);
    glActiveTexture(GL_TEXTURE0);
    set_piece_light_uniforms(program, lights.lights);
}

void RingRenderer::draw_mesh(const Program& ring, const glm::mat4& view_projection,
                             const glm::vec3& eye, bool eye_at_infinity,
                             const ShadingSettings& lights, bool cull_back, MetalMarks marks,
                             int piece_sample) const {
    const bool depth_first = piece_sample >= 1;
    // Opaque, depth-tested and written; where the stones go by visibility, no stone in their
    // stencil where the metal is drawn.
    Pipeline shade{&ring,
                   Blend::off,
                   {true, depth_first ? GLenum{GL_LEQUAL} : GLenum{GL_LESS}, true},
                   cull_back ? Cull::back : Cull::off};
    if (marks != MetalMarks::none) shade.stencil = {true, GL_ALWAYS, 0, GL_REPLACE};
    Pipeline depth_alone = shade;
    depth_alone.program = &depth_;
    depth_alone.depth.func = GL_LESS;
    depth_alone.colour_write = false;
    PipelineScope pass(depth_first ? depth_alone : shade);
    glBindVertexArray(vertex_array_.get());
    if (depth_first) {
        depth_.set("u_view_projection", view_projection);
        glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
        pass.change(shade);
    }
    ring.set("u_view_projection", view_projection);
    ring.set("u_eye", eye);
    ring.set("u_eye_at_infinity", eye_at_infinity ? 1 : 0);
    set_metal_uniforms(ring, lights, 0);
    if (depth_first) set_path_uniforms(ring, lights, piece_sample, 2);
    glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

void RingRenderer::set_path_uniforms(const Program& program, const ShadingSettings& lights,
                                     int still_sample, int first_unit) const {
    glActiveTexture(GL_TEXTURE0 + first_unit);
    glBindTexture(GL_TEXTURE_2D, sight_->nodes());
    program.set("u_bvh_nodes", first_unit);
    glActiveTexture(GL_TEXTURE0 + first_unit + 1);
    glBindTexture(GL_TEXTURE_2D, sight_->triangles());
    program.set("u_bvh_triangles", first_unit + 1);
    glActiveTexture(GL_TEXTURE0 + first_unit + 2);
    glBindTexture(GL_TEXTURE_CUBE_MAP, environment_.source().texture());
    program.set("u_environment_sharp", first_unit + 2);
    glActiveTexture(GL_TEXTURE0);
    program.set("u_h", static_cast<float>(lights.h));
    program.set("u_piece_k_s", static_cast<float>(lights.k_s));
    program.set("u_piece_k_st", static_cast<float>(lights.k_st));
    program.set("u_sample", still_sample - 1);
    // Far above a float's rounding of the metal's millimetres, far below a pixel.
    program.set("u_ray_offset_mm", static_cast<float>(2e-5 * std::max(radius_mm_, 1.0)));
}

void RingRenderer::set_piece_sight_uniforms(const Program& program, const ShadingSettings& lights,
                                            int still_sample, int first_unit) const {
    set_metal_uniforms(program, lights, first_unit);
    set_path_uniforms(program, lights, still_sample, first_unit + 2);
    // By which a stone chooses what to follow (stone_sight.glsl).
    program.set("u_environment_mean", environment_mean_);
}

Result<bool> RingRenderer::draw(const Camera& camera, double scene_radius_mm,
                                const ShadingSettings& lights_from, int still_sample,
                                MetalMarks marks) const {
    if (index_count_ == 0) return true;
    // Orthographic: every pixel looks along forward, so the eye is a direction (toward it).
    const bool at_infinity = camera.orthographic();
    const glm::vec3 eye = at_infinity ? glm::vec3(-camera.forward())
                                      : glm::vec3(-camera.forward() * camera.distance());
    const glm::mat4 vp = view_projection(camera, scene_radius_mm);
    const std::uint32_t lights = light_count_feature(lights_from.lights);
    // Closed solids wound counter-clockwise from outside: their back faces lie behind their
    // front ones, and shading them first only to be overdrawn cost a third of a halo ring's
    // metal pass on llvmpipe (bench_pieces).
    // The still view's first frame is the moving view's own (multisampled, which llvmpipe
    // shades sample by sample: the halo's 11 s at 1920×1080 with its metal seeing the piece).
    if (!follows_piece(still_sample)) {
        const bool marks_target = marks == MetalMarks::stencil_and_target;
        const Program* ring = ring_.find(lights | (marks_target ? kVisibility : 0u));
        if (ring == nullptr) return Error{"ring pass: no program marks the stones' visibility"};
        draw_mesh(*ring, vp, eye, at_infinity, lights_from, closed_, marks);
        return gl_check("ring pass");
    }
    if (marks == MetalMarks::stencil_and_target) {
        return Error{"ring pass: a frame seeing its piece marks no visibility target"};
    }
    // Its rays through the piece cost far more than a depth pass: the metal's depth is drawn
    // alone first, so that only the metal seen is shaded (bench_pieces' still metal, halo 823
    // against 656 ms, band 889 against 502). A moving frame's metal shades cheaply enough that
    // the depth pass costs more than it saves (halo 14.6 against 18.6 ms).
    const Program& ring = *ring_sees_piece_.find(kSeesPiece | lights);
    draw_mesh(ring, vp, eye, at_infinity, lights_from, closed_, marks, still_sample);
    return gl_check("ring pass (seeing its piece)");
}

Result<bool> RingRenderer::render_environment_cube(const EnvironmentCube& background,
                                                   EnvironmentCube& target,
                                                   const ShadingSettings& lights_from,
                                                   const glm::dvec3& centre) const {
    if (background.texture() == target.texture()) {
        return Error{
            "ring: environment cube: the target must differ from the background "
            "(a cube cannot be sampled while it is rendered)"};
    }
    const FramebufferScope restore;
    const int size = target.face_size();
    Framebuffer framebuffer = make_framebuffer();
    Renderbuffer depth = make_renderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, depth.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.get());
    glViewport(0, 0, size, size);
    // The ring lies between the prongs' seat around the stone (a few mm out) and its own
    // bounding sphere; near at 1/1000 of far keeps 24-bit depth ample.
    const double far_mm = std::max(1.0, 1.01 * (radius_mm_ + glm::length(centre)));
    const double near_mm = 1e-3 * far_mm;
    const glm::mat4 seen_from = glm::translate(glm::mat4(1.0f), -glm::vec3(centre));
    for (int face = 0; face < 6; ++face) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, target.texture(), 0);
        const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            return Error{"ring: environment cube: face " + std::to_string(face) +
                         " cannot be rendered to (framebuffer status " + std::to_string(status) +
                         "; RGBA16F needs EXT_color_buffer_half_float or EXT_color_buffer_float)"};
        }
        glClear(GL_DEPTH_BUFFER_BIT);
        // background.frag with a camera at the centre: a perspective ray through tangent-unit
        // image coordinates ±1 is exactly the face's 90° frustum.
        const CubeFaceBasis basis = cube_face_basis(face);
        {
            const PipelineScope background_pass(Pipeline{&background_});
            background_.set("u_cam_forward", glm::vec3(basis.forward));
            background_.set("u_cam_right", glm::vec3(basis.right));
            background_.set("u_cam_up", glm::vec3(basis.up));
            background_.set("u_cam_half", glm::vec2(1.0f));
            background_.set("u_cam_shift", glm::vec2(0.0f));
            background_.set("u_cam_distance", 1.0f);
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_CUBE_MAP, background.texture());
            background_.set("u_environment", 0);
            glBindVertexArray(vertex_array_.get());  // no attributes: fullscreen.vert needs none
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        if (index_count_ > 0) {
            // Not culled: a cube face's projection mirrors the winding, and the faces are
            // drawn only when the scene changes.
            draw_mesh(*ring_.find(light_count_feature(lights_from.lights)),
                      cube_face_projection(face, near_mm, far_mm) * seen_from, glm::vec3(centre),
                      false, lights_from, false, MetalMarks::none);
        }
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    return gl_check("ring: environment cube");
}

}  // namespace gem::gpu
