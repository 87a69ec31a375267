#pragma once
// Draws the ring with physically based metal shading, the CPU reference's model (GGX
// distribution, separable Smith masking, Schlick Fresnel from the metal's F0), lit by up to
// kMaxLights lights and by the environment filtered for its roughness (metal_environment.hpp),
// and in a still view's frames seeing its own piece (piece_sight.hpp, metal_sight.glsl);
// and renders the scene around the stone
// (environment + ring, the stone itself left out) into the six faces of a virtual cube seen
// from the stone's centre (docs/design.md, "Jewellery").

#include <cstdint>
#include <optional>

#include "gpu/environment_cube.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/metal_environment.hpp"
#include "gpu/piece_sight.hpp"
#include "gpu/program.hpp"
#include "gpu/program_variants.hpp"
#include "picture/camera.hpp"
#include "piece/ring_mesh.hpp"
#include "scene/shading.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// The 90° perspective that renders cube face `face` from the stone's centre: clip x, y =
// (p·right, p·up) of cube_face_basis(face), clip w = p·forward, so pixel (s, t) of a face
// rendered into a GL framebuffer (t = 0 at its bottom row, i.e. the face's first row in
// memory) shows the direction cube_face_direction(face, s, t). Depth maps view distances
// near_mm .. far_mm along forward onto -1..1 as a GL perspective does.
glm::mat4 cube_face_projection(int face, double near_mm, double far_mm);

enum class MetalMarks : std::uint8_t { none, stencil, stencil_and_target };

class RingRenderer {
  public:
    // An empty mesh is allowed: a loose stone, where only the environment is drawn into cubes.
    // The metal reflects `environment`, which must outlive the renderer.
    static Result<RingRenderer> make(const MetalMesh& mesh, const EnvironmentCube& environment);

    // From now on the metal of a still view's frames sees `sight`, its own piece
    // (metal_sight.glsl), and not only the environment, and so may the stones
    // (set_piece_sight_uniforms()). `environment_mean`: the environment's radiance averaged
    // over the sphere (Environment::mean_radiance()), by which the stones choose what to follow.
    Result<bool> see_piece(PieceSight sight, const glm::vec3& environment_mean);

    // Draws the ring into the bound framebuffer with depth test and depth write (the stone
    // layer has written its depth already), opaque. Uses view_projection(camera,
    // scene_radius_mm), so the ring must lie inside that sphere. `still_sample`: the frame's
    // number in a still view, whose reflected rays follow the piece (see_piece()) from its
    // second frame on; -1 while the view moves, which draws the split sum alone.
    // `marks`: in a frame whose stones go by visibility, the metal takes their stencil back
    // where it is drawn; in a multisampled one (not seeing its piece) the bound framebuffer's
    // second draw buffer is the stones' visibility target too, where the metal writes no stone
    // at the samples it takes (frame_renderer.cpp).
    Result<bool> draw(const Camera& camera, double scene_radius_mm,
                      const ShadingSettings& lights_from, int still_sample = -1,
                      MetalMarks marks = MetalMarks::none) const;

    // Whether a still view's rays may follow the piece (see_piece() succeeded).
    bool sees_piece() const { return sight_ && sight_->triangle_count() > 0; }
    // Whether draw() with `still_sample` follows the rays through the piece (and so marks no
    // visibility).
    bool follows_piece(int still_sample) const { return sees_piece() && still_sample >= 1; }
    // For a stone's program that follows its exits into the piece in the still frame
    // `still_sample` (stone_sight.glsl): the metal's and the piece's uniforms, its textures on
    // the kPieceSightUnits units from `first_unit`. Needs sees_piece().
    static constexpr int kPieceSightUnits = 5;
    void set_piece_sight_uniforms(const Program& program, const ShadingSettings& lights,
                                  int still_sample, int first_unit) const;

    // Renders background (the environment) + ring into `target`'s six faces as seen from
    // `centre` (perspective 90° per face; the stone's centre, or a group of stones'). `target`
    // must be another cube than `background`. Restores the caller's framebuffer binding and
    // viewport.
    Result<bool> render_environment_cube(const EnvironmentCube& background, EnvironmentCube& target,
                                         const ShadingSettings& lights_from,
                                         const glm::dvec3& centre = glm::dvec3(0.0)) const;

  private:
    RingRenderer(ProgramVariants ring, Program depth, Program background,
                 MetalEnvironment environment);
    // `piece_sample` ≥ 1: the still frame whose rays follow the piece (`ring` sees it): the
    // metal's depth drawn alone first, then shaded only where it is seen.
    void draw_mesh(const Program& ring, const glm::mat4& view_projection, const glm::vec3& eye,
                   bool eye_at_infinity, const ShadingSettings& lights, bool cull_back,
                   MetalMarks marks, int piece_sample = -1) const;
    // metal.glsl's uniforms, its two textures on `first_unit` and the next.
    void set_metal_uniforms(const Program& program, const ShadingSettings& lights,
                            int first_unit) const;
    // piece_path.glsl's uniforms, its three textures from `first_unit`.
    void set_path_uniforms(const Program& program, const ShadingSettings& lights, int still_sample,
                           int first_unit) const;

    ProgramVariants ring_;  // one per light count (and marking visibility), all built by make()
    ProgramVariants ring_sees_piece_;  // ... seeing its piece (SEES_PIECE): see_piece()
    Program depth_;                    // the metal's depth alone
    std::optional<PieceSight> sight_;
    float environment_mean_ = 0.0f;  // its three channels' mean
    Program background_;
    MetalEnvironment environment_;
    VertexArray vertex_array_;
    Buffer positions_;
    Buffer normals_;
    Buffer indices_;
    GLsizei index_count_ = 0;
    glm::vec3 f0_{1.0f};
    float roughness_ = 0.25f;
    double radius_mm_ = 0.0;
    bool closed_ = false;  // MetalMesh::closed: back faces culled in the frame
};

}  // namespace gem::gpu
