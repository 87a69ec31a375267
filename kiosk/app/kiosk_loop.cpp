// The kiosk's main loop: one thread polls every source (signals, display, input devices or a
// replay, catalogue switches) and draws a frame whenever the display is ready for one. Nothing
// in it blocks on the disk: views stream on the view cache's thread, catalogues are checked
// and copied on the catalogue watcher's thread.
#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include "app/kiosk_run.hpp"
#include "app/kiosk_session.hpp"
#include "app/signals.hpp"
#include "passes/crossfade.hpp"
#include "service/frame_stats.hpp"
#include "service/log.hpp"
#include "service/process_info.hpp"

namespace gem::kiosk {

namespace {

// A status line (frames, rate, memory) this often, for the journal and remote support.
constexpr double kStatusEveryS = 60.0;

int poll_timeout_ms(double now_s, double next_s) {
    if (!std::isfinite(next_s)) return -1;
    const double ms = std::ceil((next_s - now_s) * 1000.0);
    return static_cast<int>(std::clamp(ms, 0.0, 1000.0));
}

}  // namespace

int run_kiosk(const KioskRun& run) {
    auto signals = SignalFd::open();
    if (!signals) {
        log_error(signals.error());
        return 1;
    }
    auto session_made = KioskSession::make(run);
    if (!session_made) {
        log_error(session_made.error());
        return 1;
    }
    KioskSession& session = *session_made.value();

    // Every frame for a bounded run or a CSV; the last ten minutes at 60 Hz otherwise.
    const bool keep_all = !run.stats_csv.empty() || run.max_frames > 0;
    FrameStats stats(keep_all ? 0 : 36000);
    double last_status_s = monotonic_now_s();
    long frames_at_status = 0;
    bool stop = false;
    while (!stop) {
        double now = monotonic_now_s();
        std::vector<pollfd> fds;
        fds.push_back({signals.value().fd(), POLLIN, 0});
        for (int fd : session.poll_fds()) fds.push_back({fd, POLLIN, 0});
        const double deadline =
            std::min(session.next_deadline_s(now), last_status_s + kStatusEveryS);
        int timeout = poll_timeout_ms(now, deadline);
        if (session.display_ready()) timeout = 0;
        if (::poll(fds.data(), fds.size(), timeout) < 0 && errno != EINTR) {
            log_error("poll failed: " + std::string(std::strerror(errno)));
            return 1;
        }
        now = monotonic_now_s();
        for (int signal : signals.value().take()) {
            if (signal == SIGTERM || signal == SIGINT) {
                log_notice(std::string("stopping on ") +
                           (signal == SIGTERM ? "SIGTERM" : "SIGINT"));
                stop = true;
            } else if (signal == SIGHUP) {
                session.rescan_catalogues();
            } else if (signal == SIGUSR1) {
                session.request_snapshot();
            }
        }
        session.dispatch(now);
        if (session.display_ready() && !stop) {
            auto frame = session.draw_frame(now);
            if (!frame) {
                log_error(frame.error());
                return 1;
            }
            if (frame.value()) stats.add(*frame.value());
        }
        session.tick(now);
        if (now - last_status_s >= kStatusEveryS) {
            const long frames = stats.total();
            char line[160];
            std::snprintf(line, sizeof line,
                          "status: %ld frames, %.2f frames/s in the last %.0f s, "
                          "resident %.1f MiB",
                          frames,
                          static_cast<double>(frames - frames_at_status) / (now - last_status_s),
                          now - last_status_s, resident_mib());
            log_info(line);
            last_status_s = now;
            frames_at_status = frames;
        }
        if (run.max_frames > 0 && stats.total() >= run.max_frames) stop = true;
        if (run.max_seconds > 0.0 && session.seconds_running(now) >= run.max_seconds) stop = true;
        if (run.exit_after_replay && session.replay_settled(now)) stop = true;
    }
    session.finish();
    log_info("frames: " + stats.summary());
    char memory[64];
    std::snprintf(memory, sizeof memory, "resident %.1f MiB at exit", resident_mib());
    log_info(memory);
    if (!run.stats_csv.empty()) {
        std::string error;
        if (!stats.write_csv(run.stats_csv, error)) log_error(error);
    }
    return 0;
}

}  // namespace gem::kiosk
