#pragma once
// What a frame of the shading stage is made from (FrameSetup), how its stones are modelled
// (StoneModel), what a frame waits for and what it measures: shared by the frame renderer
// (frame_renderer.hpp) and the stone methods it draws with (stone_method.hpp).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gpu/table_method.hpp"
#include "gpu/trace_method.hpp"
#include "piece/metal_mesh.hpp"
#include "piece/piece.hpp"
#include "scene/environment.hpp"
#include "scene/shading.hpp"
#include "trace/tracer.hpp"

namespace gem::gpu {

enum class VisibilityPass {
    off,  // facet by facet always (to measure the two)
    // One sample a pixel always; a multisampled frame where it holds more than one stone. One
    // stone's blocks meet few facets (1.2 a block for the solitaire's diamond at 1080p), and at
    // 4x MSAA its visibility pass, writing and clearing four samples a pixel, cost more than
    // whole blocks saved: the solitaire's stone passes 1.26-1.31 times facet by facet, the
    // halo's 0.84-0.92, the band's 0.59-0.64 (bench_pieces --samples 4, 2026-12-06).
    where_it_pays,
    always,  // wherever the GL can (to test and measure a loose stone's multisampled frames)
};

struct FrameSetup {
    // The stone method, by its name in the registry (stone_method.hpp: "table", "trace",
    // "phong").
    std::string method = "table";
    std::shared_ptr<const Database> database;  // table: the stone comes from it
    Stone stone;                               // trace, phong (ignored by table)
    Material material;                         // shading-time material (colour, absorption)
    ShadingSettings shading;
    TraceSettings trace;  // trace: depth, weights, threshold
    TraceDispersion trace_dispersion = TraceDispersion::none;
    // trace: how exits are found (trace_method.hpp). `measured`: a convex stone by its fastest
    // search, timed when the renderer is made (so two renderers may choose differently, each
    // exact to float rounding), a non-convex one by its convex pieces. A convex search named
    // (walk, constants, folded) pins convex stones to it, as a comparison of two pictures
    // needs; `triangles` traces non-convex stones through their triangles (a benchmark's
    // comparison).
    ExitSearch trace_search = ExitSearch::measured;
    // Whether the stones' depth pass also writes each pixel's (or sample's) stone and entry
    // facet, so that each stone is shaded as the rectangle about it, its pixels in whole
    // blocks, not facet by facet (frame_renderer.hpp), where the method can
    // (StoneMethod::shades_by_visibility) and the GL holds the frame's samples in an integer
    // texture (visibility_target.hpp).
    VisibilityPass visibility_pass = VisibilityPass::where_it_pays;
    TableOptions table;
    // What surrounds everything; must outlive the renderer (an orthographic frame's background
    // is its radiance along the view).
    const Environment* environment = nullptr;
    int cube_face = 512;                         // virtual-cube face size, texels
    std::optional<glm::vec3> background_colour;  // else the environment shows behind
    const MetalMesh* ring = nullptr;             // optional jewellery around the stone
    // A method that draws pieces (trace, phong): a whole piece instead of `stone` and `ring`: every
    // stone drawn in its own frame (identical stones share their method's programs and stone
    // block), the piece's metal around them. Must outlive the renderer.
    const Piece* piece = nullptr;
    // A piece's kinds drawn from ray-tables instead (piece_tables.hpp), by index into
    // piece->kinds; null or missing: drawn by `method`. Each must hold its kind, orthographic,
    // every direction stored.
    std::vector<std::shared_ptr<const Database>> kind_tables;
};

// How one kind of stone is traced: the depth followed and how fire is coloured. The frame
// renderer starts every kind at the setup's (FrameSetup::trace, trace_dispersion); a piece's
// small stones may be given less (stone_models.hpp chooses it by measurement).
struct StoneModel {
    int depth = 8;
    TraceDispersion fire = TraceDispersion::none;
    bool operator==(const StoneModel&) const = default;
};

// What render() waits for: nothing (a display's swap paces it), the whole frame (timing), or
// each pass too (benchmarks: the stone pass timed alone; the extra waits cost time).
enum class FrameWait { none, frame, passes };

struct FrameStats {
    double cpu_ms = 0.0;  // from the start of the frame to glFinish returning
    // The stone passes alone (the depth pass and the shading, each between two glFinish calls;
    // FrameWait::passes only, 0 otherwise): what the method costs, without the picture's
    // other passes.
    double stone_ms = 0.0;
    double stone_depth_ms = 0.0;  // the stones' depth pass (StoneMethod::draw_depth), in stone_ms
    // The stones were shaded by the visibility pass (FrameSetup::visibility_pass), each as the
    // rectangle about it, not facet by facet.
    bool stones_by_visibility = false;
    double metal_ms = 0.0;  // the ring's or piece's metal pass alone, as stone_ms
    // The CPU's time issuing the stone pass's draws (any FrameWait): what drawing a piece's
    // stones one call each costs beyond their pixels.
    double stone_submit_ms = 0.0;
    TableFrameStats table;
    // A table showed a stand-in for a view not yet resident (TableFrameStats::complete), or
    // nothing yet: the same view drawn again looks better.
    bool stand_in = false;
};

}  // namespace gem::gpu
