#pragma once
// The virtual cube (docs/design.md, "Stage 2: shading"): six images of what surrounds the
// stone, seen from its centre, as one GL cube map in linear RGB (RGBA16F, filtered). Made from
// an Environment by sampling it at every texel, or rendered (the ring scene, see ring_scene.hpp).
// Face directions follow the GL cube-map convention (OpenGL ES 3.0 spec, table 3.21), in the
// stone frame.

#include <array>

#include <glm/glm.hpp>

#include "gpu/gl_handles.hpp"
#include "scene/environment.hpp"
#include "util/cube_faces.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class EnvironmentCube {
  public:
    // An empty cube map of `face_size`² per face, to be rendered into: RGBA16F where the GL
    // can render to half floats (EXT_color_buffer_half_float / _float), else SRGB8_ALPHA8,
    // which ES 3.0 can always render to but which clips radiance above 1.
    static Result<EnvironmentCube> allocate(int face_size);
    // Every texel set to `environment`'s radiance toward the texel's centre, with box-filtered
    // mip levels below (a rendered cube has level 0 only).
    static Result<EnvironmentCube> from_environment(const Environment& environment, int face_size);

    GLuint texture() const { return texture_.get(); }
    int face_size() const { return face_size_; }
    // Bilinear at level 0 and nothing else, for the stone's sharp lookups (shading.glsl's
    // environment): bound over the cube's own mip filter, it spares every lookup a mip-level
    // choice. On llvmpipe a textureLod of a mipmapped cube picks the level lane by lane: the
    // stone pass of trace took 1.07 times, phong's 1.13 times as long (bench_gpu, zoom 0.5,
    // medians of ten alternated runs).
    GLuint sharp_sampler() const { return sharp_sampler_.get(); }

  private:
    EnvironmentCube() = default;
    Texture texture_;
    Sampler sharp_sampler_;
    int face_size_ = 0;
};

// Whether this GL can render into RGBA16F textures (an extension in ES 3.0).
bool renders_half_float();

// The stone-frame direction through texel coordinates (s, t) in [0, 1]² of cube face `face`
// (util/cube_faces.hpp).
using gem::cube_face_direction;
// The camera basis that renders a face: looks along `forward`, image right and up, such that
// pixel (s, t) of the rendered face is cube_face_direction(face, s, t) (t = 0 at the bottom
// row of a GL framebuffer).
struct CubeFaceBasis {
    glm::dvec3 forward;
    glm::dvec3 right;
    glm::dvec3 up;
};
CubeFaceBasis cube_face_basis(int face);

}  // namespace gem::gpu
