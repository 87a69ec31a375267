#pragma once
// The measuring half of render.method = "auto" (method_probe.hpp holds the choice): for the
// stone on screen, each candidate's scene is built and a few frames are drawn into the probe's
// own off-screen pictures at the display's size (the kiosk's frame, gpu/frame_composer.hpp,
// finishing passes included), along a small turn from the start view so the table method streams
// and uploads views as it does in use. Each frame is timed to the end of the GPU's work.
//
// The probe runs a frame at a time (step()), between the frames the kiosk shows: the shop's
// screen shows the stone at once, with the safe choice, and switches to the probe's choice
// between two frames once it is known.

#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "gestures/gesture_output.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "probe/method_probe.hpp"
#include "stage/stone_scene.hpp"
#include "stage/turn_rate.hpp"
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
    double seconds = 0.0;         // from start() to the choice, the frames shown between included
    gpu::PictureOptions picture;  // the picture the frames were drawn into
};

// Walks the ladder for `stone` and chooses against `budget_ms`. A candidate stops early once
// it is certain to miss the budget (more frames over it than p90 of `frames` allows: 2 of 10),
// so a slow machine pays 4 frames per candidate, not 12; its statistic is then the p90 of the
// frames drawn. The walk stops at the first candidate that fits. A design, which has no
// tables, walks the trace's rungs only (with exact fire first where its material disperses).
class MethodProbe {
  public:
    // Errors: the first scene or the pictures cannot be made.
    static Result<std::unique_ptr<MethodProbe>> start(
        const CatalogueStone& stone, const LookChoice& look, const RenderChoice& base,
        const gpu::PictureOptions& picture, glm::ivec2 size, const ViewState& start,
        double budget_ms, const ProbeOptions& options = {});
    ~MethodProbe();

    // Draws and times the next frame (making the next candidate's scene first when its turn
    // comes); true once the choice is made (result()). Leaves the probe's target bound.
    bool step();
    bool done() const { return done_; }
    const ProbeResult& result() const { return result_; }

  private:
    MethodProbe() = default;
    void finish_candidate();

    CatalogueStone stone_;
    LookChoice look_;
    RenderChoice base_;
    ViewState start_view_;
    double budget_ms_ = 0.0;
    ProbeOptions options_;
    double began_s_ = 0.0;
    std::optional<gpu::HdrPicture> picture_;
    std::optional<gpu::RenderTarget> target_;
    ProbeResult result_;
    bool done_ = false;
    // The candidate being measured: its scene, frames drawn, budget misses, the last view.
    std::size_t index_ = 0;
    std::unique_ptr<StoneScene> scene_;
    int frame_ = 0;
    int misses_ = 0;
    TurnRate turn_;
};

// The render choice for a candidate, the rest taken from `base`.
RenderChoice apply_candidate(RenderChoice base, const MethodCandidate& candidate);

}  // namespace gem::kiosk
