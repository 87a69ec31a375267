#pragma once
// The trace method (DESIGN.md, "Methods side by side"): every pixel traced in the fragment
// shader against the stone's facet planes (convex) or triangles (non-convex) with the exact
// tracer's rules (trace/tracer.hpp: depth, weight threshold, Fresnel or thesis R/T weights)
// and shaded with shading.glsl. No tables: exact, but its cost grows with depth and facets.

#include "geometry/stone.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/program.hpp"
#include "gpu/stone_textures.hpp"
#include "trace/tracer.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class TraceMethod {
  public:
    // Uploads the stone (StoneTextures) and builds the program (convex or non-convex variant).
    static Result<TraceMethod> make(const Stone& stone);
    // Draws the stone layer for `frame` into the bound framebuffer (viewport set by caller).
    // `trace` gives depth, weight threshold, weight model (fresnel or thesis R/T factors) and
    // r/t factors; the refractive index traced with is frame.material.index().
    Result<bool> draw(const StoneFrame& frame, const TraceSettings& trace);

  private:
    TraceMethod(StoneTextures textures, Program program);
    StoneTextures textures_;
    Program program_;
    VertexArray empty_;
};

}  // namespace gem::gpu
