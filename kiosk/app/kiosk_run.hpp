#pragma once
// How one run of the kiosk is asked for: the config file, plus what the command line overrides
// for CI, benchmarks and support (a headless backend, a replayed recording, a bounded run, a
// frame-time log). A shop's kiosk runs with the config alone.

#include <filesystem>
#include <optional>
#include <string>

#include "settings/kiosk_config.hpp"

namespace gem::kiosk {

struct KioskRun {
    std::filesystem::path config_file;
    std::optional<std::string> backend;  // "drm" | "headless": overrides display.backend
    std::optional<int> width;            // headless picture size
    std::optional<int> height;
    std::optional<double> rate_hz;                   // headless frame rate (0: flat out)
    std::optional<std::filesystem::path> catalogue;  // the default catalogue directory
    std::optional<std::filesystem::path> state_dir;  // installed catalogues, inbox
    std::optional<std::filesystem::path> snapshot_dir;
    std::optional<int> snapshot_every;  // headless: a PNG every n-th frame
    bool snapshot_last = false;         // a PNG of the last frame when the run ends
    // An evemu recording replayed as if its device were plugged in (real devices are then not
    // opened, so a replay is reproducible).
    std::string replay;
    std::string replay_description;
    bool replay_loop = false;
    bool exit_after_replay = false;  // stop once the recording ends and the view has settled
    long max_frames = 0;             // stop after this many frames (0: no limit)
    double max_seconds = 0.0;        // stop after this long (0: no limit)
    std::string stats_csv;           // every frame's times, written at exit
};

// `config` as `run` overrides it: the command line outranks the file (CI and support runs say
// exactly what they need).
void apply_run_overrides(const KioskRun& run, KioskConfig& config);

// Runs until SIGTERM/SIGINT or a bound in `run`; returns the process exit status.
int run_kiosk(const KioskRun& run);

}  // namespace gem::kiosk
