#pragma once
// Installs catalogues that staff drop into the inbox (or that appear on a USB stick) without
// ever stalling the render loop. One background thread:
//   1. watches the inbox and extra directories with inotify(7), and the mount table
//      (/proc/self/mountinfo is pollable, proc(5)), so a stick mounted later is seen;
//   2. considers a catalogue directory (a directory holding catalogue.toml, or each visible
//      subdirectory of a watched directory) once its fingerprint has stayed the same for the
//      settle time;
//   3. validates it, copies it into the state directory, checks that the source did not
//      change during the copy, validates the copy (what will be mapped is what was checked:
//      the original may be on a stick that is pulled), and switches state/current to it;
//   4. hands the new Catalogue to the main loop: event_fd() becomes readable and
//      take_switch() returns it; the loop switches between frames.
// A rejected directory gets one error line. In the inbox it is set aside as <name>.rejected
// with a note saying why; elsewhere (a stick, a package's folder) it is remembered by
// fingerprint across restarts (state/refused-sources), so it is not validated again until it
// changes. Sources already installed are remembered across restarts
// (state/installed-sources), so a restart does not reinstall what is still in the inbox.
// While deliveries are refused (the config is set aside), each delivery gets one line saying
// so and stays where it is, neither set aside nor remembered.

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "catalogue/catalogue.hpp"
#include "catalogue/directory_fingerprint.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

class CatalogueWatcher {
  public:
    // How far the thread has got; for tests and the status line.
    struct Counters {
        std::uint64_t scans = 0;        // passes over the watched directories
        std::uint64_t validations = 0;  // sources validated
        std::uint64_t rejections = 0;   // sources or copies refused
        std::uint64_t copy_failures = 0;
        std::uint64_t installs = 0;
    };

    static Result<std::unique_ptr<CatalogueWatcher>> start(const CatalogueOptions& options);
    ~CatalogueWatcher();
    CatalogueWatcher(const CatalogueWatcher&) = delete;
    CatalogueWatcher& operator=(const CatalogueWatcher&) = delete;

    // Readable (poll(2) POLLIN) when take_switch() has a catalogue.
    int event_fd() const { return ready_fd_; }
    // The catalogue most recently made current, once; nothing if none is waiting.
    std::optional<Catalogue> take_switch();
    // Looks at every directory again (SIGHUP, from the systemd path unit), re-adds watches
    // for directories that appeared, and retries sources whose copy failed (a full disk may
    // have been cleared). Unchanged rejected sources stay rejected.
    void rescan();
    Counters counters() const;

  private:
    enum class Outcome { rejected, copy_failed, installed };
    struct Seen {
        DirectoryFingerprint fingerprint;
        std::chrono::steady_clock::time_point since;  // when this fingerprint was first seen
    };
    struct Handled {
        std::uint64_t hash = 0;
        Outcome outcome = Outcome::rejected;
    };

    CatalogueWatcher(const CatalogueOptions& options, int inotify_fd, int wake_fd, int ready_fd);
    void run(std::stop_token stop);
    std::vector<std::filesystem::path> candidates() const;
    // Returns the time until the next unsettled candidate settles, or nothing.
    std::optional<std::chrono::milliseconds> scan(std::stop_token stop);
    void process(const std::filesystem::path& source, const DirectoryFingerprint& fingerprint,
                 std::stop_token stop);
    void watch(const std::filesystem::path& dir);
    // Reports a source validation refused, once (set aside, or the refused-sources list).
    void refuse(const std::filesystem::path& source, std::uint64_t fingerprint,
                const std::string& why);

    const CatalogueOptions options_;
    const int inotify_fd_;
    const int wake_fd_;   // rescan() and shutdown wake the thread
    const int ready_fd_;  // eventfd for the main loop
    std::atomic<bool> rescan_requested_{false};

    // Touched by the thread only.
    std::map<std::filesystem::path, Seen> seen_;
    std::map<std::filesystem::path, Handled> handled_;
    std::set<std::uint64_t> installed_sources_;
    std::set<std::uint64_t> refused_sources_;
    std::set<std::filesystem::path> missing_logged_;

    mutable std::mutex mutex_;
    std::optional<Catalogue> switch_;  // guarded by mutex_

    std::atomic<std::uint64_t> scans_{0}, validations_{0}, rejections_{0}, copy_failures_{0},
        installs_{0};
    std::jthread thread_;  // last: started after everything it uses exists
};

}  // namespace gem::kiosk
