#pragma once
// Long arrays of float4 records on the GPU (a table view's rays, a non-convex stone's
// triangles), as RGBA32F textures kTextureWidth texels wide read with texelFetch
// (shading.glsl's texel_of).

#include <cstddef>

#include "gpu/gl_handles.hpp"
#include "util/result.hpp"

namespace gem::gpu {

inline constexpr int kTextureWidth = 1024;

// A float RGBA texture of `texels` texels laid out kTextureWidth wide, nearest filtering, for
// texelFetch. Errors when it would exceed GL_MAX_TEXTURE_SIZE rows.
Result<Texture> upload_texel_array(const float* rgba, std::size_t texels, const char* what);

}  // namespace gem::gpu
