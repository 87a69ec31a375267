#pragma once
// The trace method (DESIGN.md, "Methods side by side"): exact tracing per fragment of the
// stone pass, with the exact tracer's rules (trace/tracer.hpp: depth, weight threshold,
// Fresnel or thesis R/T weights), shaded with shading.glsl. No tables, so it is exact at every
// view. Convex stones find each exit by walking the facets from a first guess (trace.frag,
// trace/facet_walk.hpp); non-convex ones test their triangles.

#include "geometry/stone.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/program.hpp"
#include "gpu/stone_geometry.hpp"
#include "trace/tracer.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// How the trace method colours fire (DESIGN.md, "Where gemkiosk goes beyond the thesis").
enum class TraceDispersion {
    none,         // one index, n(D)
    first_order,  // exit directions moved by their derivative with respect to n, per channel
    exact,        // each colour channel traced at its own index (three times the work)
};

class TraceMethod {
  public:
    // Uploads the stone (StoneGeometry) and builds the program (convex or non-convex variant).
    static Result<TraceMethod> make(const Stone& stone);
    // Draws the stone layer for `frame` into the bound framebuffer (viewport set by caller).
    // `trace` gives depth, weight threshold, weight model (fresnel or thesis R/T factors) and
    // r/t factors; the refractive index traced with is frame.material.index().
    Result<bool> draw(const StoneFrame& frame, const TraceSettings& trace,
                      TraceDispersion dispersion = TraceDispersion::none);

  private:
    TraceMethod(StoneGeometry geometry, Program program, double radius_mm);
    StoneGeometry geometry_;
    Program program_;
    double radius_mm_ = 0.0;
};

}  // namespace gem::gpu
