#include "probe/method_probe_run.hpp"

#include <GLES3/gl3.h>

#include <chrono>
#include <cmath>

#include "gpu/frame_composer.hpp"
#include "picture/camera.hpp"
#include "service/process_info.hpp"
#include "util/elapsed.hpp"

namespace gem::kiosk {

namespace {

// The probe's view `turn_deg` along its turn from `start`.
ViewState turned(const ViewState& start, double turn_deg) {
    ViewState view = start;
    view.azimuth_deg += turn_deg;
    return view;
}

}  // namespace

RenderChoice apply_candidate(RenderChoice base, const MethodCandidate& candidate) {
    base.method = candidate.method;
    base.blend = candidate.blend;
    base.max_level = candidate.max_level;
    base.exact_fire = candidate.exact_fire;
    return base;
}

MethodProbe::~MethodProbe() = default;

Result<std::unique_ptr<MethodProbe>> MethodProbe::start(
    const CatalogueStone& stone, const LookChoice& look, const RenderChoice& base,
    const gpu::PictureOptions& picture, glm::ivec2 size, const ViewState& start, double budget_ms,
    const ProbeOptions& options) {
    std::unique_ptr<MethodProbe> p(new MethodProbe());
    p->began_s_ = monotonic_now_s();
    p->stone_ = stone;
    p->look_ = look;
    p->base_ = base;
    p->start_view_ = start;
    p->budget_ms_ = budget_ms;
    p->options_ = options;
    p->result_.picture = picture;
    auto hdr = gpu::HdrPicture::make(size.x, size.y, picture);
    if (!hdr) return Error{hdr.error()};
    p->picture_.emplace(std::move(hdr).value());
    auto target = gpu::RenderTarget::make(size.x, size.y);
    if (!target) return Error{target.error()};
    p->target_.emplace(std::move(target).value());
    // The first rung's scene holds the database, which decides how many rungs there are: the
    // table level the stone's size needs.
    const std::vector<MethodCandidate> ladder = method_ladder(0);
    auto first = StoneScene::make(stone, look, apply_candidate(base, ladder.front()));
    if (!first) return Error{first.error()};
    ProbeResult& r = p->result_;
    if (first.value()->has_database()) {
        int needed_level = 0;
        const Database& db = first.value()->database();
        auto camera = first.value()->camera(start, size);
        if (camera) {
            needed_level = static_cast<int>(
                gpu::table_level_for(db, db.camera().field_mm / camera.value().pixel_size()));
        }
        r.candidates = method_ladder(needed_level, db.params().dispersion);
    } else {
        // A design has no tables: its rungs are the trace's, with exact fire first where its
        // material disperses (the fire a design shows, stone_scene.cpp).
        r.candidates =
            rungs_without_tables(method_ladder(0, first.value()->stone().material.disperses()));
    }
    r.frame_ms.resize(r.candidates.size());
    // With dispersion the ladder starts with a rung the first scene does not draw.
    if (r.candidates.front().exact_fire == ladder.front().exact_fire) {
        p->scene_ = std::move(first).value();
    }
    return p;
}

bool MethodProbe::step() {
    if (done_) return true;
    if (!scene_) {
        auto made =
            StoneScene::make(stone_, look_, apply_candidate(base_, result_.candidates[index_]));
        // A piece's small stones modelled as the kiosk models them when it shows the scene.
        if (!made || !made.value()->choose_stone_models({target_->width(), target_->height()})) {
            finish_candidate();  // never measured, never chosen
            return done_;
        }
        scene_ = std::move(made).value();
        frame_ = 0;
        misses_ = 0;
        turn_.restart();
    }
    const glm::ivec2 size(target_->width(), target_->height());
    const ViewState view = turned(start_view_, options_.turn_deg_per_frame * frame_);
    auto camera = scene_->camera(view, size);
    if (!camera) {
        finish_candidate();
        return done_;
    }
    // As the kiosk's draw does: the turn's angular velocity lets the stone method prepare
    // ahead (the table streams the way a drag does).
    const double frame_s = std::isfinite(budget_ms_) ? budget_ms_ / 1000.0 : 1.0 / 60.0;
    const glm::dvec3 omega = turn_.next(camera.value().forward(), frame_ * frame_s);
    // The frame shown before this one is not this one's cost.
    glFinish();
    const auto begin = std::chrono::steady_clock::now();
    // The kiosk's own frame, as a screen draws it (no wait inside the frame), then waited for
    // to the end of the GPU's work. Every probe frame is a moving one.
    picture_->begin_frame(false);
    gpu::FrameView frame_view = scene_->frame_view(view, size);
    frame_view.omega = omega;
    auto drawn = gpu::compose_frame(
        {.renderer = &scene_->renderer(), .view = frame_view, .picture = &*picture_}, *target_);
    const bool finished = drawn && drawn.value().scene_error.empty();
    glFinish();
    const double ms = ms_since(begin);
    const int timed = frame_ - options_.warmup_frames;
    ++frame_;
    if (timed < 0) return false;
    std::vector<double>& times = result_.frame_ms[index_];
    // A failed frame is recorded as not-a-number: choose_method drops it.
    times.push_back(finished ? ms : std::nan(""));
    const int allowed_misses =
        options_.frames -
        static_cast<int>(std::ceil(kFrameTimeQuantile * static_cast<double>(options_.frames)));
    if (finished && ms > budget_ms_) ++misses_;
    if (misses_ > allowed_misses || timed + 1 >= options_.frames) finish_candidate();
    return done_;
}

void MethodProbe::finish_candidate() {
    scene_.reset();  // one candidate's GL objects at a time
    result_.choice =
        choose_method(result_.frame_ms, budget_ms_, refractive_rungs(result_.candidates));
    ++index_;
    if (result_.choice.fits || index_ >= result_.candidates.size()) {
        done_ = true;
        result_.seconds = monotonic_now_s() - began_s_;
        picture_.reset();  // the probe's pictures are not kept
        target_.reset();
    }
}

}  // namespace gem::kiosk
