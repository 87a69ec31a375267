#include "app/kiosk_run.hpp"

namespace gem::kiosk {

void apply_run_overrides(const KioskRun& run, KioskConfig& config) {
    if (run.backend) config.display.backend = *run.backend;
    if (run.width) config.display.headless_width = *run.width;
    if (run.height) config.display.headless_height = *run.height;
    if (run.rate_hz) config.display.headless_rate_hz = *run.rate_hz;
    if (run.catalogue) config.catalogue.default_dir = *run.catalogue;
    if (run.state_dir) {
        config.catalogue.state_dir = *run.state_dir;
        config.catalogue.inbox_dir = *run.state_dir / "inbox";
    }
    if (run.snapshot_dir) config.snapshot.dir = *run.snapshot_dir;
    if (run.snapshot_every) config.snapshot.every_n_frames = *run.snapshot_every;
}

}  // namespace gem::kiosk
