// gemkiosk: the fullscreen kiosk a shop runs (docs/design.md, "Layout": kiosk/). With only a
// config file it is the product; the other options serve CI, benchmarks and remote support.
#include <CLI/CLI.hpp>

#include <iostream>

#include "app/config_check.hpp"
#include "app/kiosk_run.hpp"
#include "settings/kiosk_config.hpp"

int main(int argc, char** argv) {
    gem::kiosk::KioskRun run;
    run.config_file = gem::kiosk::kDefaultConfigFile;
    CLI::App app{"gemkiosk: faceted gemstones with real refraction, fullscreen"};
    app.add_option("-c,--config", run.config_file, "configuration file (TOML)");
    std::string check;
    app.add_option("--check-config", check,
                   "print every problem of this config file and exit, 1 on any (run it after each "
                   "edit, before a restart)");
    std::string backend;
    app.add_option("--backend", backend, "drm or headless (overrides display.backend)")
        ->check(CLI::IsMember({"drm", "headless"}));
    std::optional<int> width, height;
    app.add_option("--width", width, "headless picture width")->check(CLI::Range(1, 16384));
    app.add_option("--height", height, "headless picture height")->check(CLI::Range(1, 16384));
    std::optional<double> rate;
    app.add_option("--rate", rate, "headless frames per second (0: as fast as it renders)")
        ->check(CLI::Range(0.0, 1000.0));
    std::string catalogue, state, snapshots;
    app.add_option("--catalogue", catalogue, "default catalogue directory");
    app.add_option("--state-dir", state, "state directory (installed catalogues, inbox)");
    app.add_option("--snapshot-dir", snapshots, "where snapshots are written");
    std::optional<int> every;
    app.add_option("--snapshot-every", every, "headless: a PNG every N frames (0: none)")
        ->check(CLI::Range(0, 1000000));
    app.add_flag("--snapshot-last", run.snapshot_last, "a PNG of the last frame at exit");
    app.add_option("--replay", run.replay, "replay an evemu recording instead of the devices");
    app.add_option("--replay-desc", run.replay_description,
                   "the recording's device description (.desc), if not in the recording");
    app.add_flag("--replay-loop", run.replay_loop, "replay the recording again and again");
    app.add_flag("--exit-after-replay", run.exit_after_replay,
                 "stop when the recording has played and the view has settled");
    app.add_option("--frames", run.max_frames, "stop after N frames")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--seconds", run.max_seconds, "stop after S seconds")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--stats", run.stats_csv, "write every frame's times to this CSV at exit");
    CLI11_PARSE(app, argc, argv);
    if (!check.empty()) return gem::kiosk::check_config(check, std::cout) == 0 ? 0 : 1;

    if (!backend.empty()) run.backend = backend;
    run.width = width;
    run.height = height;
    run.rate_hz = rate;
    if (!catalogue.empty()) run.catalogue = catalogue;
    if (!state.empty()) run.state_dir = state;
    if (!snapshots.empty()) run.snapshot_dir = snapshots;
    run.snapshot_every = every;
    return gem::kiosk::run_kiosk(run);
}
