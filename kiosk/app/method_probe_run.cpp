#include "app/method_probe_run.hpp"

#include <chrono>
#include <cmath>

#include "app/kiosk_frame.hpp"
#include "app/process_info.hpp"
#include "render/camera.hpp"

namespace gem::kiosk {

namespace {

Result<Camera> probe_camera(const StoneScene& scene, const ViewState& start, double turn_deg,
                            const gpu::RenderTarget& target) {
    ViewState view = start;
    view.azimuth_deg += turn_deg;
    return scene.camera(view, {target.width(), target.height()});
}

// Times whole frames of one scene, the picture's finishing passes included; stops once more
// frames missed the budget than p90 allows.
std::vector<double> measure(StoneScene& scene, gpu::HdrPicture& scene_picture,
                            gpu::RenderTarget& target, const ViewState& start, double budget_ms,
                            const ProbeOptions& options) {
    // A piece's small stones modelled as the kiosk models them when it shows the scene.
    if (!scene.choose_stone_models({target.width(), target.height()})) return {};
    const int total = options.warmup_frames + options.frames;
    const int allowed_misses =
        options.frames -
        static_cast<int>(std::ceil(kFrameTimeQuantile * static_cast<double>(options.frames)));
    std::vector<double> times;
    int misses = 0;
    glm::dvec3 last_forward(0.0);
    const double frame_s = std::isfinite(budget_ms) ? budget_ms / 1000.0 : 1.0 / 60.0;
    for (int i = 0; i < total; ++i) {
        auto camera = probe_camera(scene, start, options.turn_deg_per_frame * i, target);
        if (!camera) break;
        // As the kiosk's draw does: the turn's angular velocity lets the stone method prepare
        // ahead (the table streams the way a drag does).
        const glm::dvec3 forward = camera.value().forward();
        const glm::dvec3 omega =
            i > 0 ? glm::cross(last_forward, forward) / frame_s : glm::dvec3(0.0);
        last_forward = forward;
        const auto begin = std::chrono::steady_clock::now();
        // The kiosk's own frame (kiosk_frame.hpp), as a screen draws it (no wait inside the
        // frame), then waited for to the end of the GPU's work.
        auto drawn = draw_kiosk_frame(&scene, &camera.value(), omega, gpu::FrameWait::none,
                                      scene_picture, target);
        const bool finished = drawn && drawn.value().scene_error.empty();
        glFinish();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
                .count();
        if (i < options.warmup_frames) continue;
        // A failed frame is recorded as not-a-number: choose_method drops it.
        times.push_back(finished ? ms : std::nan(""));
        if (finished && ms > budget_ms && ++misses > allowed_misses) break;
    }
    return times;
}

}  // namespace

RenderChoice apply_candidate(RenderChoice base, const MethodCandidate& candidate) {
    base.method = candidate.method;
    base.blend = candidate.blend;
    base.max_level = candidate.max_level;
    base.exact_fire = candidate.exact_fire;
    return base;
}

Result<ProbeResult> probe_methods(const CatalogueStone& stone, const LookChoice& look,
                                  const RenderChoice& base, gpu::HdrPicture& scene_picture,
                                  gpu::RenderTarget& target, const ViewState& start,
                                  double budget_ms, const ProbeOptions& options) {
    const double began_s = monotonic_now_s();
    ProbeResult result;
    // The first rung's scene holds the database, which decides how many rungs there are: the
    // table level the stone's size needs.
    std::vector<MethodCandidate> ladder = method_ladder(0);
    auto first = StoneScene::make(stone, look, apply_candidate(base, ladder.front()));
    if (!first) return Error{first.error()};
    if (first.value()->has_database()) {
        int needed_level = 0;
        const Database& db = first.value()->database();
        auto camera = probe_camera(*first.value(), start, 0.0, target);
        if (camera) {
            needed_level = static_cast<int>(
                gpu::table_level_for(db, db.camera().field_mm / camera.value().pixel_size()));
        }
        result.candidates = method_ladder(needed_level, db.params().dispersion);
    } else {
        // A design has no tables: its rungs are the trace's, with exact fire first where its
        // material disperses (the fire a design shows, stone_scene.cpp).
        result.candidates = method_ladder(0, first.value()->stone().material.disperses());
        std::erase_if(result.candidates,
                      [](const MethodCandidate& c) { return c.method != "trace"; });
    }
    result.frame_ms.resize(result.candidates.size());
    std::unique_ptr<StoneScene> scene = std::move(first).value();
    // With dispersion the ladder starts with a rung the first scene does not draw.
    if (result.candidates.front().exact_fire != ladder.front().exact_fire) scene.reset();
    for (std::size_t i = 0; i < result.candidates.size(); ++i) {
        if (i > 0 || !scene) {
            scene.reset();  // one scene's GL objects at a time
            auto made = StoneScene::make(stone, look, apply_candidate(base, result.candidates[i]));
            if (!made) continue;  // never measured, never chosen
            scene = std::move(made).value();
        }
        result.frame_ms[i] = measure(*scene, scene_picture, target, start, budget_ms, options);
        result.choice =
            choose_method(result.frame_ms, budget_ms, refractive_rungs(result.candidates));
        if (result.choice.fits) break;
    }
    result.seconds = monotonic_now_s() - began_s;
    return result;
}

}  // namespace gem::kiosk
