#pragma once
// The measuring half of render.method = "auto" (method_probe.hpp holds the choice): for the
// stone about to be shown, each candidate's scene is built and a few frames are drawn into the
// kiosk's own off-screen pictures at the display's size (finishing passes included), along a small
// turn from the start view so the table method streams and uploads views as it does in use. Each
// frame is timed to the end of the GPU's work.

#include <vector>

#include "app/method_probe.hpp"
#include "app/stone_scene.hpp"
#include "gestures/gesture_output.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

struct ProbeOptions {
    int warmup_frames = 2;          // not timed: shader compilation, the first views' decode
    int frames = 10;                // timed per candidate
    double turn_deg_per_frame = 3;  // azimuth step: a brisk drag at 60 Hz
};

struct ProbeResult {
    std::vector<MethodCandidate> candidates;
    std::vector<std::vector<double>> frame_ms;  // per candidate; empty: not measured
    MethodChoice choice;
    double seconds = 0.0;  // the probe's whole cost, scene builds included
};

// Walks the ladder for `stone` and chooses against `budget_ms`. A candidate stops early once
// it is certain to miss the budget (more frames over it than p90 of `frames` allows: 2 of 10),
// so a slow machine pays 4 frames per candidate, not 12; its statistic is then the p90 of the
// frames drawn. The walk stops at the first candidate that fits. A design, which has no
// tables, walks the trace's rungs only (with exact fire first where its material disperses).
// Errors: the first scene cannot be made. Leaves `target` bound.
Result<ProbeResult> probe_methods(const CatalogueStone& stone, const LookChoice& look,
                                  const RenderChoice& base, gpu::HdrPicture& scene_picture,
                                  gpu::RenderTarget& target, const ViewState& start,
                                  double budget_ms, const ProbeOptions& options = {});

// The render choice for a candidate, the rest taken from `base`.
RenderChoice apply_candidate(RenderChoice base, const MethodCandidate& candidate);

}  // namespace gem::kiosk
