#pragma once
// The per-frame inputs every GPU stone method shares, and the uniforms they become in
// camera.glsl and shading.glsl. The camera, lights and cube come in the piece's frame (a loose
// stone's own) and are moved into the stone's by its placement.

#include "geometry/stone.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/program.hpp"
#include "gpu/program_variants.hpp"
#include "gpu/visibility_target.hpp"
#include "optics/spectrum.hpp"
#include "picture/camera.hpp"
#include "piece/placement.hpp"
#include "scene/shading.hpp"

namespace gem::gpu {

class RingRenderer;

// What a frame of a still view traces differently from a moving one (HdrPicture::still_frame());
// the default is a moving frame.
struct StillFrame {
    // Its own wavelengths (nm, per channel) and how its traces mix, for spectral fire; null:
    // the channels' dominant ones. The trace's fire is traced at them (trace_method.hpp).
    const StillWavelengths* wavelengths = nullptr;
    // The depth the trace follows in this frame where deeper than its own
    // (TraceSettings::max_depth); 0: its own.
    int depth = 0;
    // Its number in the still view (0 its first), by which its stochastic samples differ
    // (the rays through the piece, piece_path.glsl); -1 while the view moves.
    int index = -1;
};

struct StoneFrame {
    const Stone* stone = nullptr;
    Material material;  // may differ from stone->material: colour changes without a rebuild
    Camera camera;
    ShadingSettings shading;
    const EnvironmentCube* environment = nullptr;
    double cube_half_mm = 0.0;      // the virtual cube's half side; 0 puts it at infinity
    double scene_radius_mm = 10.0;  // holds everything drawn (depth range, view_projection)
    // Where the stone sits in the piece (identity: a loose stone). The stone is shaded in its
    // own frame: its camera and lights are moved into it, and its exits back out to the cube.
    Placement placement{};
    // What this frame of a still view traces differently (HdrPicture::still_frame()).
    StillFrame still{};
    // In a piece's still view after its first frame: the piece its exits follow
    // (stone_sight.glsl); null: the cube alone.
    const RingRenderer* piece_sight = nullptr;
    // Where the visibility pass ran (FrameRenderer::render): its target, holding each pixel's
    // (or sample's) entry facet and stone, and this stone's number (1 + its place in the frame)
    // in the stencil where it is seen; no texture: the stone is drawn facet by facet.
    VisibilityAttachment visibility{};
    std::uint32_t stone_id = 0;
};

// The frame's camera as the stone sees it: its rays in the stone's frame (Camera::in_frame).
Camera stone_camera(const StoneFrame& frame);

// Sets camera.glsl's uniforms for tracing the stone of `frame` in its own frame: the stone's
// camera, and stone.vert's u_view_projection that places the stone's vertices in the piece, so the
// depth of every stone and of the metal is measured alike.
void set_camera_uniforms(const Program& program, const StoneFrame& frame);
// That u_view_projection alone: the frame's view_projection() times the stone's placement.
glm::mat4 stone_view_projection(const StoneFrame& frame);

// Sets camera.glsl's uniforms: each pixel's ray of `camera`.
void set_ray_uniforms(const Program& program, const Camera& camera);

// The matrix that rasterises exactly what Camera::ray sees: clip x and y span the image
// (right, up), depth runs front to back over the sphere of radius `scene_radius_mm` about the
// stone's centre (everything drawn must lie inside it: the ring as well as the stone). The
// stone pass and the ring share it, so each hides the other where it is nearer.
glm::mat4 view_projection(const Camera& camera, double scene_radius_mm);

// The shading.glsl features `frame` needs compiled in (program_variants.hpp: the thesis'
// shading model, a cube at infinity, an absorbing body, the number of lights, a whole
// specular exponent, and its exits followed into its piece: stone_sight.glsl).
std::uint32_t shading_features(const StoneFrame& frame);

// u_light_position (w = 1: a point, 0: a direction) and u_light_colour of the first kMaxLights
// lights, moved into the frame `placement` puts in the piece; their count is compiled into the
// program (light_count_feature).
void set_light_uniforms(const Program& program, const std::vector<Light>& lights,
                        const Placement& placement = {});
// u_piece_light_position and u_piece_light_colour (metal.glsl): the lights in the piece's frame,
// for the metal's shading and for rays that follow the piece.
void set_piece_light_uniforms(const Program& program, const std::vector<Light>& lights);

// Where shading_features(frame) follows the exits into the piece: what piece_path.glsl and
// stone_sight.glsl read, their textures on RingRenderer::kPieceSightUnits units from
// `first_unit`. Nothing otherwise.
void set_piece_sight_uniforms(const Program& program, const StoneFrame& frame, int first_unit);

// A sampler bound to a texture unit for as long as this lives (it overrides the filter of
// whatever texture a later pass binds to the unit).
class SamplerBinding {
  public:
    SamplerBinding(GLuint unit, GLuint sampler);
    SamplerBinding(const SamplerBinding&) = delete;
    SamplerBinding& operator=(const SamplerBinding&) = delete;
    ~SamplerBinding();

  private:
    GLuint unit_;
};

// What every stone method's shading reads of `frame` (phong's too): the environment cube on
// texture unit `unit`, with its sharp sampler for as long as the binding returned lives (keep
// it until the stone's draws are made), the stone's frame, the lights, k_s, h, alpha and the
// stone's colour.
[[nodiscard]] SamplerBinding set_surface_uniforms(const Program& program, const StoneFrame& frame,
                                                  int unit);
// The traced methods' shading.glsl: the surface's uniforms, and the cube's size, the stone's
// place, k_st and absorption.
[[nodiscard]] SamplerBinding set_shading_uniforms(const Program& program, const StoneFrame& frame,
                                                  int unit);

}  // namespace gem::gpu
