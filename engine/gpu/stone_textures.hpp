#pragma once
// The stone's geometry on the GPU, for the obstruction test (table method) and for tracing in
// the fragment shader (trace method): facet planes (n, d) one RGBA32F texel each, and for
// non-convex stones the triangles, three texels each (a corner's xyz, w = the triangle's facet).
// Textures are kTextureWidth texels wide (shading.glsl's kTexWidth), as many rows as needed.

#include "geometry/stone.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/program.hpp"
#include "util/result.hpp"

namespace gem::gpu {

inline constexpr int kTextureWidth = 1024;

class StoneTextures {
  public:
    // Errors: more facets or triangles than a texture of the GL's size limit holds.
    static Result<StoneTextures> upload(const Stone& stone);

    // Binds the planes to texture unit `unit` and the triangles to `unit + 1`, and sets
    // u_planes, u_triangles and u_triangle_count on `program` (in use).
    void bind(const Program& program, int unit) const;
    bool convex() const { return convex_; }
    int facet_count() const { return facets_; }
    int triangle_count() const { return triangles_; }

  private:
    StoneTextures() = default;
    Texture planes_;
    Texture triangles_texture_;
    bool convex_ = true;
    int facets_ = 0;
    int triangles_ = 0;
};

// A float RGBA texture of `texels` texels laid out kTextureWidth wide, nearest filtering, for
// texelFetch. Errors when it would exceed GL_MAX_TEXTURE_SIZE rows.
Result<Texture> upload_texel_array(const float* rgba, std::size_t texels, const char* what);

}  // namespace gem::gpu
