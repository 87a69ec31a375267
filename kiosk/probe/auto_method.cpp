#include "probe/auto_method.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "service/log.hpp"
#include "stage/start_view.hpp"

namespace gem::kiosk {

namespace {

const std::string& chosen_name(const ProbeResult& probe) {
    return probe.candidates[probe.choice.index].name;
}

double chosen_ms(const ProbeResult& probe) {
    const auto& statistic = probe.choice.statistic_ms[probe.choice.index];
    return statistic ? *statistic : std::nan("");
}

}  // namespace

void AutoMethod::choose(const ProbeSubject& subject, bool first_frame_shown, RenderChoice& render) {
    // Once per session, as the first stone is shown: a catalogue switch or a new stone keeps
    // the choice, since the cost is set by the picture's pixels and the stone's share of them
    // (the start view frames every ring the same way), and a probe halves the frame rate for a
    // few seconds. A display reopened at another size keeps it too.
    waiting_ = false;
    if (probed_size_ == subject.size) return;
    if (probed_size_ && first_frame_shown) {
        log_info("render.method auto: keeping the choice measured at " +
                 std::to_string(probed_size_->x) + "x" + std::to_string(probed_size_->y));
        probed_size_ = subject.size;
        return;
    }
    if (!std::isfinite(subject.budget_ms)) {
        // No target rate (a headless display drawing as fast as it can): nothing to hold, so
        // the most accurate candidate without spending seconds measuring it (exact fire
        // draws as plain trace where a database stores no dispersion).
        probed_size_ = subject.size;
        const MethodCandidate best = method_ladder(0, true).front();
        render = apply_candidate(render, best);
        log_info("render.method auto: no frame rate to hold; using " + best.name);
        return;
    }
    // The probe builds its own picture and scenes (a second of llvmpipe's time at 1080p): the
    // first frame is shown with the table before it starts.
    if (!first_frame_shown) {
        waiting_ = true;
        return;
    }
    // Marked before probing: a probe that fails is not tried again once frames are on screen.
    probed_size_ = subject.size;
    with_extras_.reset();
    subject_ = subject;
    auto probe = MethodProbe::start(subject.stone, subject.look, subject.render, subject.picture,
                                    subject.size, kStartView, subject.budget_ms);
    if (!probe) {
        log_error("render.method auto: no probe (" + probe.error() + "); using table");
        return;
    }
    probe_ = std::move(probe).value();
    log_info("render.method auto: measuring the methods while the stone is shown with the table");
}

std::optional<AutoMethod::Choice> AutoMethod::step(const PictureExtras& extras) {
    if (!probe_ || !probe_->step()) return std::nullopt;
    ProbeResult r = probe_->result();
    probe_.reset();
    Choice choice;
    if (r.choice.valid && !r.choice.fits && (extras.samples > 1 || extras.glare) && !with_extras_) {
        // Probed again without MSAA and glare, still between frames shown.
        gpu::PictureOptions without = r.picture;
        without.samples = 1;
        without.glare = 0.0;
        auto again = MethodProbe::start(subject_->stone, subject_->look, subject_->render, without,
                                        subject_->size, kStartView, r.choice.budget_ms);
        if (again) {
            with_extras_ = std::move(r);
            probe_ = std::move(again).value();
            return std::nullopt;
        }
        log_error("render.method auto: no probe without MSAA and glare (" + again.error() + ")");
    }
    if (with_extras_ && r.choice.valid) {
        char line[240];
        std::snprintf(line, sizeof line,
                      "picture: MSAA and glare off: no method held the %.1f ms budget with them "
                      "(%s p90 %.1f ms); without them %s p90 %.1f ms; still views are still "
                      "averaged, over up to %d frames",
                      r.choice.budget_ms, chosen_name(*with_extras_).c_str(),
                      chosen_ms(*with_extras_), chosen_name(r).c_str(), chosen_ms(r),
                      r.picture.still_frames);
        log_warning(line);
        r.seconds += with_extras_->seconds;  // both probes: the choice's whole cost
        choice.picture = r.picture;
    } else if (with_extras_) {
        r = std::move(*with_extras_);  // without the extras nothing drew: keep them
    }
    with_extras_.reset();
    if (!r.choice.valid) {
        log_error("render.method auto: no candidate drew a frame; using table");
        return choice;
    }
    choice.render = apply_candidate(subject_->render, r.candidates[r.choice.index]);
    char cost[96];
    std::snprintf(cost, sizeof cost, " (%dx%d, probe took %.2f s)", subject_->size.x,
                  subject_->size.y, r.seconds);
    const std::string line = describe_choice(r.candidates, r.choice) + cost;
    if (r.choice.fits) {
        log_info(line);
    } else {
        char why[112];
        std::snprintf(why, sizeof why,
                      "; no method holds the frame rate, using the first refracting one within "
                      "%.2fx of the fastest",
                      kNearFastest);
        log_warning(line + why);
    }
    return choice;
}

}  // namespace gem::kiosk
