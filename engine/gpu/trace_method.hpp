#pragma once
// The trace method (docs/design.md, "Methods side by side"): exact tracing per fragment of the
// stone pass, with the exact tracer's rules (trace/tracer.hpp: depth, weight threshold,
// Fresnel or thesis R/T weights), shaded with shading.glsl. No tables, so it is exact at every
// view. A non-convex stone is traced as its convex pieces (trace/convex_pieces.hpp), or by
// its triangles where it does not split into few. Convex stones find each exit one of three
// ways, all exact (trace.frag): by walking the facets from a first guess (a handful of planes
// read from the uniform block per bounce; trace/facet_walk.hpp), by testing every plane,
// written into the shader as constants (no reads, no divergence), or, for a stone with two
// mirrors or more, by folding the ray into one wedge of its symmetry and testing the planes
// there, also constants (trace/folded_exit.hpp). Which is fastest depends on the GPU, so by
// default make() times each on a small picture and keeps the fastest. Shading model, cube
// and fire are compiled into the program a draw uses (program_variants.hpp), built on first
// use.

#include <iterator>
#include <string>

#include "geometry/stone.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/program_variants.hpp"
#include "gpu/stone_geometry.hpp"
#include "trace/tracer.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// How the trace method colours fire (docs/design.md, "Physical weights and shading-time
// material").
enum class TraceDispersion {
    none,         // one index, n(D)
    first_order,  // exit directions moved by their derivative with respect to n, per channel
    exact,        // each colour channel traced at its own index (three times the work)
    // Exact while the view moves; a still view's frames each trace their own wavelengths
    // (StoneFrame::spectrum, optics/spectrum.hpp: StillSpectrum), so the still picture
    // converges to the spectral integral. A convex stone's still frames do so with any fire
    // when given wavelengths; a non-convex stone's only with this (and no fire while moving).
    spectral,
};
// "none", "first-order", "exact", "spectral": for logs and benchmark tables.
const char* to_string(TraceDispersion fire);

// How exits are found: a convex stone's three searches (or the fastest of them, measured), and
// a non-convex stone's two: its convex pieces (trace/convex_pieces.hpp), where it splits into
// few, or its triangles.
enum class ExitSearch { walk, constants, folded, measured, pieces, triangles };
const char* to_string(ExitSearch search);

class TraceMethod {
  public:
    // Uploads the stone (StoneGeometry) and builds the program (the convex variant `search`
    // names: an error for `folded` on a stone that does not fold; `measured` builds each and
    // keeps the fastest on a 64×64 test picture, drawn off screen; the caller's framebuffer
    // and viewport are kept, as for `pieces` and `triangles`, which name no convex search. A
    // non-convex stone's pieces unless `search` is `triangles`, whatever convex search it names).
    static Result<TraceMethod> make(const Stone& stone, ExitSearch search = ExitSearch::measured);
    // Draws the stone layer for `frame` into the bound framebuffer (viewport set by caller).
    // `trace` gives depth, weight threshold, weight model (fresnel or thesis R/T factors) and
    // r/t factors; the refractive index traced with is frame.material.index().
    Result<bool> draw(const StoneFrame& frame, const TraceSettings& trace,
                      TraceDispersion dispersion = TraceDispersion::none);
    // The stone's depth alone for `frame` (StoneMethod::draw_depth), within the depth pass's
    // `pass` with `depth` (stone_depth, or stone_visibility, which takes the stone's stencil).
    void draw_depth(const StoneFrame& frame, const Program& depth, PipelineScope& pass) const;
    // A multisampled visibility target's samples within the rectangle about the stone cleared
    // to no stone, before any stone's visibility pass (the scissor test on; the caller keeps
    // and restores it): the stone's shading pass reads every sample of its rectangle's pixels,
    // and one no stone covers this frame would still hold an earlier frame's stone and facet.
    void clear_visibility(const StoneFrame& frame) const;

    // The search in use, and what the measurement gave a convex stone's (ms for the test
    // picture; 0 when not measured), also as a log phrase.
    ExitSearch exit_search() const { return search_; }
    double measured_ms(ExitSearch search) const {
        const auto i = static_cast<std::size_t>(search);  // the convex searches come first
        return i < std::size(measured_ms_) ? measured_ms_[i] : 0.0;
    }
    std::string measurement() const;

  private:
    TraceMethod(StoneGeometry geometry, ProgramVariants programs, bool convex);
    // The program of `features`, attached to the stone's block when it is first built.
    Result<const Program*> program(std::uint32_t features);
    // The rectangle about the stone in normalised device coordinates (x0, y0, x1, y1), a pixel
    // more each way, within the picture; nullopt where none of it is on the picture.
    std::optional<glm::vec4> rectangle(const StoneFrame& frame) const;
    // The stone as the rectangle about it, where the visibility pass ran (StoneFrame::visibility).
    void draw_rectangle(const Program& program, const StoneFrame& frame) const;
    StoneGeometry geometry_;
    ProgramVariants programs_;
    VertexArray no_attributes_;  // the rectangle's corners come from the vertex index
    bool convex_ = true;
    ExitSearch search_ = ExitSearch::walk;
    double measured_ms_[3] = {};  // walk, constants, folded
};

}  // namespace gem::gpu
