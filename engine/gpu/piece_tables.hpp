#pragma once
// A piece whose stones of some kinds are drawn from ray-tables and the rest by another method
// (the trace). Tables serve the stones that need them: a non-convex stone (a heart, a CAD
// design) traced by testing every triangle costs far more per pixel than a convex one, and its
// tables, built once, draw it in a fraction of that (docs/pieces.md, "Stones from tables": a
// sixth for the heart at 1080p).
//
// Each placed stone of a kind with tables is drawn from them in its own frame (the table
// method's stone camera), so the tables must be of that very stone (its description scaled to
// the piece's width: `gemtables build --width-mm`) and store every direction
// (`--min-elevation -90`): a piece turns its stones every way. The views of every such stone
// are prefetched along the turn, and each keeps its views on the GPU.

#include <cstddef>
#include <memory>
#include <vector>

#include "geometry/stone.hpp"
#include "gpu/frame_setup.hpp"
#include "gpu/stone_method.hpp"
#include "piece/placement.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// `rest`: the method made for every kind (it draws those without tables). `kinds`: the piece's
// kinds; `stone_kinds[i]` and `placements[i]`: its stone i's kind and placement.
// setup.kind_tables[k], where set, must hold kind k (same_stored_stone) with orthographic,
// whole-sphere tables; else an error names it.
Result<std::unique_ptr<StoneMethod>> with_kind_tables(std::unique_ptr<StoneMethod> rest,
                                                      const FrameSetup& setup,
                                                      const std::vector<const Stone*>& kinds,
                                                      const std::vector<std::size_t>& stone_kinds,
                                                      const std::vector<Placement>& placements);

}  // namespace gem::gpu
