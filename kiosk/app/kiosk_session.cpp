#include "app/kiosk_session.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "app/catalogue_setup.hpp"
#include "app/scene_build.hpp"
#include "app/snapshot.hpp"
#include "catalogue/catalogue_store.hpp"
#include "gpu/frame_composer.hpp"
#include "input/touch_mapping.hpp"
#include "picture/camera.hpp"
#include "service/log.hpp"
#include "service/process_info.hpp"
#include "stage/start_view.hpp"

namespace gem::kiosk {

Result<std::unique_ptr<KioskSession>> KioskSession::make(const KioskRun& run) {
    std::unique_ptr<KioskSession> s(new KioskSession(run));
    s->started_s_ = monotonic_now_s();
    auto configured = s->configure();
    if (!configured) return Error{configured.error()};
    return s;
}

KioskSession::~KioskSession() = default;

Result<bool> KioskSession::configure() {
    // The last good config lives in the state folder the kiosk is started with, never one the
    // file names (settings/last_good_config.hpp).
    const std::filesystem::path kept_in = started_state_dir(run_);
    const ResolvedConfig resolved = resolve_config(run_.config_file, kept_in);
    for (const std::string& error : resolved.errors) log_error(error);
    config_ = resolved.config;
    set_log_threshold(config_.log_level);
    apply_run_overrides(run_, config_);
    render_ = render_choice(config_);

    selection_ = std::make_unique<SceneSelection>(config_.backgrounds, config_.lightings);
    catalogues_ = std::make_unique<CatalogueFeed>(catalogue_setup(config_, resolved, kept_in));
    if (const Catalogue* shown = catalogues_->shown()) selection_->set_catalogue(*shown);
    design_tables_ =
        std::make_unique<DesignTables>(config_.designs, config_.catalogue.state_dir / "tables");

    if (config_.display.backend == "drm") {
        seat_ = Seat::open();
    }
    if (!run_.replay.empty()) {
        EvemuReplayOptions replay;
        replay.events_path = run_.replay;
        replay.description_path = run_.replay_description;
        replay.loop = run_.replay_loop;
        auto opened = EvemuReplay::open(replay);
        if (!opened) return Error{opened.error()};
        log_info("replaying " + run_.replay + " (" + opened.value().device_name() + ", " +
                 std::to_string(opened.value().event_count()) + " events)");
        replay_.emplace(std::move(opened).value());
    } else if (seat_) {
        std::shared_ptr<Seat> seat = seat_;
        input_ = std::make_unique<InputManager>(
            config_.input,
            [seat](const std::string& path) {
                const int fd = seat->open(path);
                return fd >= 0 ? fd : -errno;
            },
            [seat](int fd) { seat->close(fd); });
    } else {
        input_ = std::make_unique<InputManager>(config_.input);
    }
    gestures_ = std::make_unique<GestureController>(config_.gestures, kStartView);
    screen_ = std::make_unique<Screen>(config_.display, config_.picture, seat_);
    open_screen_if_due(monotonic_now_s());
    return true;
}

void KioskSession::open_screen_if_due(double now_s) {
    switch (screen_->open_if_due(now_s)) {
        case Screen::Opening::unchanged:
            return;
        case Screen::Opening::failed:
            notifier_.set_frames_expected(false);
            return;
        case Screen::Opening::opened:
            break;
    }
    const Display& display = screen_->display();
    const glm::ivec2 size = display.picture_size();
    auto rotation = touch_rotation_from_options(config_.input.rotation_deg, display.rotation_deg());
    if (!rotation) log_error(rotation.error());
    const TouchMapping mapping(config_.input.calibration, rotation ? rotation.value() : 0,
                               glm::dvec2(size));
    if (input_) input_->set_mapping(mapping);
    if (replay_) replay_->set_mapping(mapping);
    gestures_->set_picture_size(glm::dvec2(size));
    scene_stale_ = true;
    notifier_.set_frames_expected(true);
}

std::vector<int> KioskSession::poll_fds() const {
    std::vector<int> fds;
    if (screen_->open() && screen_->display().event_fd() >= 0) {
        fds.push_back(screen_->display().event_fd());
    }
    // The display polls the seat while it exists; without one the seat is still served, so a
    // VT switch is acknowledged even while the kiosk waits for a screen.
    if (!screen_->open() && seat_ && seat_->fd() >= 0) fds.push_back(seat_->fd());
    if (input_) fds.push_back(input_->fd());
    catalogues_->add_poll_fds(fds);
    if (design_tables_ && design_tables_->fd() >= 0) fds.push_back(design_tables_->fd());
    return fds;
}

double KioskSession::next_deadline_s(double now_s) const {
    double next = std::numeric_limits<double>::infinity();
    if (!screen_->open()) next = std::min(next, screen_->next_try_s());
    if (screen_->open() && screen_->display().timeout_ms() >= 0) {
        next = std::min(next, now_s + screen_->display().timeout_ms() / 1000.0);
    }
    if (replay_) next = std::min(next, replay_->next_due_s());
    if (input_) next = std::min(next, input_->next_retry_s());
    if (screen_->open() && screen_->display().ready()) {
        next = std::min(next, next_frame_allowed_s());
    }
    next = std::min(next, notifier_.next_ping_s(now_s));
    // A check of a design's tables runs on a thread with no descriptor to wake the loop.
    if (design_tables_ && design_tables_->busy()) next = std::min(next, now_s + 0.1);
    return next;
}

double KioskSession::next_frame_allowed_s() const {
    // render.frame_rate_hz caps the rate below the display's (a cooler, quieter kiosk).
    const double rate = config_.render.frame_rate_hz;
    if (rate <= 0.0 || last_frame_start_s_ < 0.0) return 0.0;
    return last_frame_start_s_ + 1.0 / rate;
}

bool KioskSession::display_ready() const {
    return screen_->open() && screen_->display().ready() &&
           monotonic_now_s() >= next_frame_allowed_s();
}

void KioskSession::dispatch(double now_s) {
    open_screen_if_due(now_s);
    if (screen_->open()) screen_->display().dispatch();
    if (!screen_->open() && seat_) seat_->dispatch();
    std::vector<InputEvent> events;
    if (input_) events = input_->dispatch(now_s);
    if (replay_) events = replay_->poll(now_s);
    for (const InputEvent& event : events) {
        const double t = std::visit([](const auto& e) { return e.time_s; }, event);
        if (oldest_unshown_input_s_ < 0.0) oldest_unshown_input_s_ = t;
        last_input_s_ = t;
        gestures_->on_event(event);
    }
    switch (catalogues_->dispatch()) {
        case CatalogueFeed::Arrival::none:
            break;
        case CatalogueFeed::Arrival::completed:
            // The same catalogue's other entries join the one on screen, whose scene stays.
            if (!selection_->complete_catalogue(*catalogues_->shown())) scene_stale_ = true;
            break;
        case CatalogueFeed::Arrival::switched:
            hold_picture(now_s);
            selection_->set_catalogue(*catalogues_->shown());
            scene_stale_ = true;
            break;
    }
    // A design's tables came into or went out of use: its scene is made again between frames.
    if (design_tables_ &&
        design_tables_->dispatch(selection_->has_stone() ? &selection_->stone() : nullptr)) {
        scene_stale_ = true;
    }
}

void KioskSession::rescan_catalogues() {
    catalogues_->rescan();
}

void KioskSession::hold_picture(double now_s) {
    if (screen_->open() && first_frame_shown_) {
        screen_->crossfade().hold(screen_->picture(), now_s, config_.crossfade_s);
    }
}

void KioskSession::apply_actions(double now_s) {
    for (GestureAction action : gestures_->take_actions()) {
        if (!selection_->has_stone() && action == GestureAction::next_stone) continue;
        hold_picture(now_s);
        if (action == GestureAction::next_stone) selection_->next_stone();
        if (action == GestureAction::next_preset) selection_->next_preset();
        scene_stale_ = true;
        log_info("now " + selection_->describe());
    }
}

void KioskSession::rebuild_scene(double now_s) {
    (void)now_s;
    scene_stale_ = false;
    scene_.reset();  // the old scene's GL objects go before the new one's are made
    if (!selection_->has_stone()) return;
    if (config_.render.method == kAutoMethod) choose_render_method();
    frames_since_scene_ = 0;
    BuiltScene built = build_scene(selection_->stone(), selection_->look(), render_,
                                   *design_tables_, screen_->picture_size());
    scene_tables_ = std::move(built.tables);
    if (!built.scene) return;
    scene_ = std::move(built.scene);
    screen_->scene_picture().set_display(display_transform(config_.picture, selection_->look()));
    gestures_->set_elevation_limits(scene_->min_elevation_deg(), scene_->max_elevation_deg());
}

void KioskSession::choose_render_method() {
    auto_method_.choose(
        {.stone = selection_->stone(),
         .look = selection_->look(),
         .render = render_,
         .picture = screen_->scene_picture().options(),
         .size = screen_->picture_size(),
         .budget_ms = frame_budget_ms(config_.render.frame_rate_hz, screen_->display().refresh_hz(),
                                      config_.render.auto_headroom)},
        first_frame_shown_, render_);
}

void KioskSession::advance_probe(double now_s) {
    const gpu::HdrPicture& picture = screen_->scene_picture();
    const PictureExtras extras{.samples = picture.samples(),
                               .glare = picture.options().glare > 0.0 && picture.high_range()};
    const std::optional<AutoMethod::Choice> choice = auto_method_.step(extras);
    if (!choice) return;
    if (choice->picture) {
        auto remade = screen_->remake_scene_picture(*choice->picture);
        if (!remade) log_error(remade.error());
    }
    if (!choice->render) return;
    render_ = *choice->render;
    // The stone drawn again with the choice, faded in over the table's picture.
    hold_picture(now_s);
    scene_stale_ = true;
}

bool KioskSession::same_view(const ViewState& a, const ViewState& b) {
    return a.azimuth_deg == b.azimuth_deg && a.elevation_deg == b.elevation_deg &&
           a.roll_deg == b.roll_deg && a.zoom == b.zoom;
}

gpu::FrameView KioskSession::frame_view(double now_s) {
    gpu::FrameView view = scene_->frame_view(gestures_->view(), screen_->picture_size());
    view.omega = turn_.next(view_forward(view.camera), now_s);
    return view;
}

Result<std::optional<FrameRecord>> KioskSession::draw_frame(double now_s) {
    if (!screen_->open()) return std::optional<FrameRecord>{};
    gpu::HdrPicture& scene_picture = screen_->scene_picture();
    gpu::RenderTarget& picture = screen_->picture();
    CrossFade& crossfade = screen_->crossfade();
    gestures_->advance(now_s);
    apply_actions(now_s);
    const bool rebuilt = scene_stale_;
    if (scene_stale_) rebuild_scene(now_s);

    // A still view is refined frame by frame (hdr_picture.hpp) for the time it is given; once
    // it has all its frames or its time, and no cross-fade is drawn over it, the picture on
    // screen is shown again undrawn.
    const ViewState view = gestures_->view();
    const bool still = !rebuilt && last_view_ && same_view(*last_view_, view);
    last_view_ = view;
    scene_picture.begin_frame(still, now_s);
    log_still_view_settled();
    const bool fading = crossfade.active(now_s);
    const bool redraw = !scene_picture.settled() || fading || faded_last_frame_;
    faded_last_frame_ = fading;

    FrameRecord record;
    record.start_s = monotonic_now_s();
    record.probing = auto_method_.probing();
    record.still = scene_picture.still_frame().index;
    last_frame_start_s_ = record.start_s;
    bool stand_in = false;  // a view not yet resident was stood in for (FrameStats::stand_in)
    if (redraw) {
        // Headless frames are timed to the end of the GPU's work; on a screen the swap bounds it.
        gpu::FrameRequest request{
            .wait = config_.display.backend != "drm" ? gpu::FrameWait::frame : gpu::FrameWait::none,
            .picture = &scene_picture};
        if (scene_) {
            request.renderer = &scene_->renderer();
            request.view = frame_view(now_s);
        }
        auto drawn = gpu::compose_frame(request, picture);
        if (!drawn) return Error{drawn.error()};
        if (!drawn.value().scene_error.empty()) log_error(drawn.value().scene_error);
        if (const auto& stats = drawn.value().stats) {
            const gpu::TableFrameStats& t = stats->table;
            record.streaming_ms = t.acquire_ms + t.upload_ms + t.wait_ms;
            stand_in = stats->stand_in;
        }
        auto faded = crossfade.draw(picture, now_s);
        if (!faded) return Error{faded.error()};
        // The fade drew over the whole picture: the next frame finishes it whole.
        if (fading) scene_picture.forget_target();
    }
    if (!redraw) {
        changed_.reset(picture.width(), picture.height());
    } else if (fading) {
        changed_.reset(picture.width(), picture.height(), true);
    } else {
        changed_ = scene_picture.target_region();
    }
    auto presented = screen_->display().present(picture, changed_);
    if (!presented) return Error{"display: " + presented.error()};
    if (!presented.value()) return std::optional<FrameRecord>{};  // drawn, but not shown
    const double done_s = monotonic_now_s();
    if (!redraw) {
        // On screen again, which the watchdog counts, but not a frame drawn: the figures are
        // about drawing.
        last_present_s_ = done_s;
        notifier_.frame_presented(done_s);
        write_requested_snapshot();
        advance_probe(done_s);
        start_replay(done_s);
        record.drawn = false;
        return std::optional<FrameRecord>(record);
    }
    record.draw_ms = (done_s - record.start_s) * 1000.0;
    // What the next still frame is judged by; and without a mean, whether a still view needs
    // drawing again.
    scene_picture.frame_drawn(record.draw_ms, stand_in);
    if (last_present_s_ >= 0.0) record.interval_ms = (done_s - last_present_s_) * 1000.0;
    if (oldest_unshown_input_s_ >= 0.0) {
        record.latency_ms = (done_s - oldest_unshown_input_s_) * 1000.0;
        oldest_unshown_input_s_ = -1.0;
    }
    last_present_s_ = done_s;
    ++frame_number_;
    notifier_.frame_presented(done_s);
    // The frame budget is the moving frames': a still frame traced deeper (picture.still_depth)
    // costs more by choice, and only while the view settles.
    if (scene_ && selection_->has_stone() &&
        scene_picture.still_frame().depth <= config_.render.depth) {
        design_tables_->frame_drawn(
            selection_->stone(), scene_tables_, frames_since_scene_++, record.draw_ms,
            frame_budget_ms(config_.render.frame_rate_hz, screen_->display().refresh_hz(),
                            config_.render.auto_headroom));
    }

    if (!first_frame_shown_) {
        first_frame_shown_ = true;
        char line[160];
        std::snprintf(line, sizeof line, "first frame on screen %.2f s after the process started",
                      seconds_since_process_start());
        log_info(line);
        notifier_.ready("showing " + selection_->describe());
        if (auto_method_.waiting_for_first_frame()) choose_render_method();
    }
    start_replay(done_s);
    const int every = config_.snapshot.every_n_frames;
    if (every > 0 && frame_number_ % every == 0) {
        char name[32];
        std::snprintf(name, sizeof name, "frame-%06ld.png", frame_number_);
        write_snapshot_file(name);
    }
    write_requested_snapshot();
    advance_probe(done_s);
    return std::optional<FrameRecord>(record);
}

void KioskSession::log_still_view_settled() {
    const gpu::HdrPicture& picture = screen_->scene_picture();
    if (!picture.settled()) {
        still_view_logged_ = false;
        return;
    }
    // Without a mean a still view is its one frame: nothing was refined to say.
    if (still_view_logged_ || !picture.averages()) return;
    still_view_logged_ = true;
    const gpu::StillSchedule& s = picture.still_schedule();
    char line[160];
    std::snprintf(line, sizeof line, "still view refined: %d frames in %.1f s, to depth %d",
                  picture.still_frames_drawn(), s.settled_after_s(), s.deepest());
    log_info(line);
}

void KioskSession::start_replay(double now_s) {
    // A replay starts once the kiosk is on screen with its chosen method, so neither start-up
    // nor the method probe eats its first gestures, and its frames are the chosen method's.
    if (!replay_ || replay_->started() || !first_frame_shown_ || auto_method_.probing() ||
        scene_stale_) {
        return;
    }
    replay_->start(now_s);
}

void KioskSession::write_requested_snapshot() {
    if (!snapshot_requested_) return;
    snapshot_requested_ = false;
    write_snapshot_file("snapshot.png");
}

void KioskSession::write_snapshot_file(const std::string& name) {
    auto written = write_snapshot(screen_->picture(), config_.snapshot.dir / name);
    if (!written) {
        log_error(written.error());
    } else {
        log_debug("snapshot " + (config_.snapshot.dir / name).string());
    }
}

void KioskSession::tick(double now_s) {
    notifier_.tick(now_s);
}

bool KioskSession::replay_settled(double now_s) const {
    if (!replay_ || !replay_->finished() || !first_frame_shown_) return false;
    // The last event is long enough ago for a fling's spin to have died away (eight half-lives
    // leave under 0.4 %), and a frame has been drawn since.
    const double rest_s = 8.0 * config_.gestures.inertia_half_life_s;
    // ... and the still view has all its averaged frames, so the last picture is the settled
    // one whatever the machine's speed.
    // ... and render.method auto has made its choice and shows it.
    return now_s - last_input_s_ > rest_s && last_present_s_ - last_input_s_ > rest_s &&
           screen_->open() && screen_->scene_picture().refined() && !auto_method_.probing() &&
           !scene_stale_;
}

void KioskSession::finish() {
    notifier_.stopping();
    const ViewState v = gestures_->view();
    char line[160];
    std::snprintf(
        line, sizeof line, "last view: azimuth %.2f°, elevation %.2f°, roll %.2f°, zoom %.3f; %s",
        v.azimuth_deg, v.elevation_deg, v.roll_deg, v.zoom, selection_->describe().c_str());
    log_info(line);
    if (run_.snapshot_last && screen_->open()) write_snapshot_file("last.png");
    // GL objects go while their context is current, then the display (which restores the mode
    // the screen had before the kiosk).
    auto_method_.stop();
    scene_.reset();
    screen_->close();
    design_tables_.reset();  // a build still running is stopped
}

}  // namespace gem::kiosk
