#pragma once
// Everything one kiosk run holds, and what the main loop asks of it each time round: the
// config, the screen (app/screen.hpp), the input devices or a replay, the gestures, the
// catalogue on screen and the one arriving, the scene drawn, snapshots and systemd
// notification. kiosk_loop.cpp owns the loop itself.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/kiosk_run.hpp"
#include "app/screen.hpp"
#include "builds/design_tables.hpp"
#include "catalogue/catalogue_feed.hpp"
#include "display/seat.hpp"
#include "gestures/gesture_controller.hpp"
#include "gpu/tile_set.hpp"
#include "input/evemu_replay.hpp"
#include "input/input_manager.hpp"
#include "probe/auto_method.hpp"
#include "service/frame_stats.hpp"
#include "service/service_notifier.hpp"
#include "settings/kiosk_config.hpp"
#include "stage/picture_choice.hpp"
#include "stage/scene_selection.hpp"
#include "stage/stone_scene.hpp"
#include "stage/turn_rate.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

class KioskSession {
  public:
    static Result<std::unique_ptr<KioskSession>> make(const KioskRun& run);
    ~KioskSession();

    std::vector<int> poll_fds() const;
    // The next time dispatch() must run even if no descriptor becomes readable.
    double next_deadline_s(double now_s) const;
    bool display_ready() const;

    // Reads input, page-flip and catalogue events; opens a missing display when it is time.
    void dispatch(double now_s);
    // Draws and presents one frame; nothing when there is nothing to draw on.
    Result<std::optional<FrameRecord>> draw_frame(double now_s);
    // Watchdog pings and snapshots requested from outside.
    void tick(double now_s);

    void rescan_catalogues();
    void request_snapshot() { snapshot_requested_ = true; }
    double seconds_running(double now_s) const { return now_s - started_s_; }
    // The replay has played every event, the view has come to rest and its picture is refined.
    bool replay_settled(double now_s) const;
    // Leaves the screen as it found it and tells systemd the kiosk is stopping.
    void finish();

  private:
    explicit KioskSession(const KioskRun& run) : run_(run) {}
    Result<bool> configure();
    // The screen opened when it is missing and due: what depends on its size follows it.
    void open_screen_if_due(double now_s);
    double next_frame_allowed_s() const;
    // The picture on screen held, to fade from it into what changed (none before the first).
    void hold_picture(double now_s);
    void rebuild_scene(double now_s);
    // render.method = auto (probe/auto_method.hpp): asked as a scene is made and after the
    // first frame; a probe frame after each frame shown, its choice applied once made.
    void choose_render_method();
    void advance_probe(double now_s);
    void apply_actions(double now_s);
    void write_snapshot_file(const std::string& name);
    void write_requested_snapshot();  // SIGUSR1's, after a frame is on screen
    // Once a still view has its frames or its time: how far it was refined, in one line.
    void log_still_view_settled();
    void start_replay(double now_s);  // once the first frame and the probe's choice are shown
    // The gestures' view this frame, with how fast it turns.
    gpu::FrameView frame_view(double now_s);
    static bool same_view(const ViewState& a, const ViewState& b);

    KioskRun run_;
    KioskConfig config_;
    double started_s_ = 0.0;
    std::shared_ptr<Seat> seat_;
    // Before everything that holds GL objects, so that it goes after them.
    std::unique_ptr<Screen> screen_;

    std::unique_ptr<InputManager> input_;
    std::optional<EvemuReplay> replay_;
    std::unique_ptr<GestureController> gestures_;
    std::vector<InputEvent> pending_input_;
    double oldest_unshown_input_s_ = -1.0;
    double last_input_s_ = -1.0;

    std::unique_ptr<CatalogueFeed> catalogues_;
    std::unique_ptr<SceneSelection> selection_;
    std::unique_ptr<StoneScene> scene_;
    bool scene_stale_ = true;
    int frames_since_scene_ = 0;
    std::unique_ptr<DesignTables> design_tables_;  // designs' tables, built in the background
    DesignTables::KindTables scene_tables_;        // the tables the scene was made with
    RenderChoice render_;
    AutoMethod auto_method_;

    ServiceNotifier notifier_;
    bool first_frame_shown_ = false;
    long frame_number_ = 0;
    double last_present_s_ = -1.0;
    // What the picture changed since the last one presented: nothing when it was not drawn
    // again, all of it under a cross-fade (kept between frames: a frame allocates nothing).
    gpu::TileSet changed_;
    double last_frame_start_s_ = -1.0;
    bool snapshot_requested_ = false;
    std::optional<ViewState> last_view_;  // the last frame's, to tell a still view
    bool faded_last_frame_ = false;
    bool still_view_logged_ = false;  // this still view's "refined" line is in the log
    TurnRate turn_;                   // the view's, frame by frame
};

}  // namespace gem::kiosk
