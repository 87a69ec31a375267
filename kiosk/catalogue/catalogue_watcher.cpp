#include "catalogue/catalogue_watcher.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

#include "catalogue/catalogue_store.hpp"
#include "catalogue/event_fd.hpp"
#include "catalogue/manifest.hpp"
#include "catalogue/validate.hpp"
#include "service/log.hpp"

namespace gem::kiosk {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

// No IN_MODIFY: a file being written would wake the thread for every write; the settle timer
// looks again anyway while a directory is unsettled, and a finished write gives IN_CLOSE_WRITE.
constexpr std::uint32_t kWatchMask = IN_CREATE | IN_DELETE | IN_MOVED_FROM | IN_MOVED_TO |
                                     IN_CLOSE_WRITE | IN_ATTRIB | IN_DELETE_SELF | IN_ONLYDIR;

// Every event inotify has queued.
void drain(int fd) {
    char buffer[4096];
    while (::read(fd, buffer, sizeof buffer) > 0) {
    }
}

}  // namespace

Result<std::unique_ptr<CatalogueWatcher>> CatalogueWatcher::start(const CatalogueOptions& options) {
    const int inotify_fd = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (inotify_fd < 0) return Error{std::string("inotify_init1: ") + std::strerror(errno)};
    const int wake_fd = make_event_fd();
    const int ready_fd = make_event_fd();
    if (wake_fd < 0 || ready_fd < 0) {
        const int err = errno;
        ::close(inotify_fd);
        if (wake_fd >= 0) ::close(wake_fd);
        if (ready_fd >= 0) ::close(ready_fd);
        return Error{std::string("eventfd: ") + std::strerror(err)};
    }
    std::unique_ptr<CatalogueWatcher> watcher(
        new CatalogueWatcher(options, inotify_fd, wake_fd, ready_fd));
    watcher->thread_ = std::jthread([w = watcher.get()](std::stop_token stop) { w->run(stop); });
    return watcher;
}

CatalogueWatcher::CatalogueWatcher(const CatalogueOptions& options, int inotify_fd, int wake_fd,
                                   int ready_fd)
    : options_(options), inotify_fd_(inotify_fd), wake_fd_(wake_fd), ready_fd_(ready_fd) {}

CatalogueWatcher::~CatalogueWatcher() {
    thread_.request_stop();
    signal_event_fd(wake_fd_);
    if (thread_.joinable()) thread_.join();
    ::close(inotify_fd_);
    ::close(wake_fd_);
    ::close(ready_fd_);
}

std::optional<Catalogue> CatalogueWatcher::take_switch() {
    drain_event_fd(ready_fd_);
    std::lock_guard lock(mutex_);
    return std::exchange(switch_, std::nullopt);
}

void CatalogueWatcher::rescan() {
    rescan_requested_ = true;
    signal_event_fd(wake_fd_);
}

CatalogueWatcher::Counters CatalogueWatcher::counters() const {
    return {scans_.load(), validations_.load(), rejections_.load(), copy_failures_.load(),
            installs_.load()};
}

void CatalogueWatcher::watch(const fs::path& dir) {
    // Adding a watch for an inode already watched returns the same one (inotify_add_watch(2)),
    // so every scan can simply add them all; the kernel drops those of removed directories.
    if (::inotify_add_watch(inotify_fd_, dir.c_str(), kWatchMask) < 0 && errno != ENOENT) {
        log_debug("cannot watch " + dir.string() + ": " + std::strerror(errno));
    }
}

std::vector<fs::path> CatalogueWatcher::candidates() const {
    std::vector<fs::path> roots{options_.inbox_dir};
    roots.insert(roots.end(), options_.extra_dirs.begin(), options_.extra_dirs.end());
    std::vector<fs::path> out;
    for (const fs::path& root : roots) {
        std::error_code ec;
        if (!fs::is_directory(root, ec)) continue;
        // A stick may hold one catalogue at its root.
        if (fs::exists(root / kManifestName, ec)) {
            out.push_back(root);
            continue;
        }
        std::vector<fs::path> inside;
        for (const auto& entry : fs::directory_iterator(root, ec)) {
            std::error_code type_ec;
            // Hidden directories are left alone, so staff (or rsync) can write a catalogue
            // under a dot name and rename it when done.
            // A catalogue refused before is set aside under <name>.rejected.
            const std::string name = entry.path().filename().string();
            const bool rejected =
                name.size() > std::strlen(kRejectedSuffix) && name.ends_with(kRejectedSuffix);
            if (name.front() != '.' && !rejected && entry.is_directory(type_ec) &&
                !entry.is_symlink(type_ec)) {
                inside.push_back(entry.path());
            }
        }
        std::sort(inside.begin(), inside.end());
        out.insert(out.end(), inside.begin(), inside.end());
    }
    return out;
}

void CatalogueWatcher::run(std::stop_token stop) {
    remove_partial_copies(options_.state_dir);
    for (const std::uint64_t f : read_sources(options_.state_dir, kInstalledSources)) {
        installed_sources_.insert(f);
    }
    for (const std::uint64_t f : read_sources(options_.state_dir, kRefusedSources)) {
        refused_sources_.insert(f);
    }
    // The mount table changes when a stick is mounted; poll reports it as POLLPRI (proc(5)).
    const int mounts_fd = ::open("/proc/self/mountinfo", O_RDONLY | O_CLOEXEC);
    while (!stop.stop_requested()) {
        rescan_requested_ = false;
        const std::optional<std::chrono::milliseconds> wait = scan(stop);
        ++scans_;
        pollfd fds[3] = {{inotify_fd_, POLLIN, 0}, {wake_fd_, POLLIN, 0}, {mounts_fd, POLLPRI, 0}};
        const int timeout = wait ? static_cast<int>(std::max<std::int64_t>(wait->count(), 1)) : -1;
        if (::poll(fds, mounts_fd >= 0 ? 3 : 2, timeout) < 0 && errno != EINTR) {
            log_error(std::string("catalogue watcher: poll: ") + std::strerror(errno));
            break;
        }
        drain(inotify_fd_);
        drain_event_fd(wake_fd_);
        if (rescan_requested_) {
            // A full disk may have been cleared since: try those sources again.
            std::erase_if(handled_,
                          [](const auto& h) { return h.second.outcome == Outcome::copy_failed; });
        }
    }
    if (mounts_fd >= 0) ::close(mounts_fd);
}

std::optional<std::chrono::milliseconds> CatalogueWatcher::scan(std::stop_token stop) {
    std::vector<fs::path> roots{options_.inbox_dir};
    roots.insert(roots.end(), options_.extra_dirs.begin(), options_.extra_dirs.end());
    for (const fs::path& root : roots) watch(root);

    std::optional<std::chrono::milliseconds> next;
    const std::vector<fs::path> found = candidates();
    for (const fs::path& source : found) {
        if (stop.stop_requested()) return next;
        Result<DirectoryFingerprint> fingerprint = fingerprint_directory(source);
        if (!fingerprint) continue;  // vanishing or unreadable: looked at again next time
        for (const fs::path& dir : fingerprint.value().directories) watch(dir);
        const Clock::time_point now = Clock::now();
        auto [it, fresh] = seen_.try_emplace(source, Seen{fingerprint.value(), now});
        if (!fresh && !(it->second.fingerprint == fingerprint.value())) {
            it->second = Seen{fingerprint.value(), now};
        }
        const std::uint64_t hash = fingerprint.value().hash;
        if (auto h = handled_.find(source); h != handled_.end() && h->second.hash == hash) continue;
        if (installed_sources_.count(hash) != 0) {
            handled_[source] = {hash, Outcome::installed};
            continue;
        }
        if (refused_sources_.count(hash) != 0) {
            handled_[source] = {hash, Outcome::rejected};
            log_debug("catalogue at " + source.string() + " was refused before and is unchanged");
            continue;
        }
        if (fingerprint.value().unpacking) it->second.since = now;  // a package half unpacked
        const auto quiet =
            std::chrono::duration_cast<std::chrono::milliseconds>(now - it->second.since);
        if (quiet < options_.settle_time || fingerprint.value().unpacking) {
            const auto left = options_.settle_time - quiet;
            next = next ? std::min(*next, left) : left;
            continue;
        }
        process(source, fingerprint.value(), stop);
        // A source that changed during its copy waits to settle again.
        if (handled_.count(source) == 0) {
            next = next ? std::min(*next, options_.settle_time) : options_.settle_time;
        }
    }
    // Forget directories that went away, so one put back is looked at afresh.
    std::erase_if(seen_, [&](const auto& s) {
        return std::find(found.begin(), found.end(), s.first) == found.end();
    });
    std::erase_if(handled_, [&](const auto& h) {
        return std::find(found.begin(), found.end(), h.first) == found.end();
    });
    return next;
}

void CatalogueWatcher::process(const fs::path& source, const DirectoryFingerprint& fingerprint,
                               std::stop_token stop) {
    const std::string from = " (from " + source.string() + ")";
    if (!options_.deliveries_refused_because.empty()) {
        // Handled as refused for this fingerprint, but neither set aside nor remembered: a kiosk
        // started on a good config looks at it again.
        handled_[source] = {fingerprint.hash, Outcome::rejected};
        log_error("catalogue at " + source.string() + " not installed: " +
                  options_.deliveries_refused_because + "; it is left where it is");
        ++rejections_;
        return;
    }
    handled_[source] = {fingerprint.hash, Outcome::rejected};
    ++validations_;
    Result<Catalogue> checked = validate_catalogue(source, options_.trust, stop);
    if (stop.stop_requested()) return;
    if (!checked) {
        refuse(source, fingerprint.hash, checked.error() + from);
        ++rejections_;  // after the line: tests wait on the count, then read the log
        return;
    }
    const std::string name = checked.value().name;
    Result<fs::path> copy = copy_catalogue(source, options_.state_dir, name, stop);
    std::error_code ec;
    if (stop.stop_requested()) {
        if (copy) fs::remove_all(copy.value(), ec);
        return;
    }
    if (!copy) {
        log_error("catalogue '" + name + "' not installed: copy failed: " + copy.error() + from);
        handled_[source].outcome = Outcome::copy_failed;
        ++copy_failures_;
        return;
    }
    Result<DirectoryFingerprint> after = fingerprint_directory(source);
    if (!after || !(after.value() == fingerprint)) {
        fs::remove_all(copy.value(), ec);
        handled_.erase(source);
        seen_.erase(source);
        log_info("catalogue '" + name + "' changed while it was copied; waiting for it to settle" +
                 from);
        return;
    }
    Result<Catalogue> installed = validate_catalogue(copy.value(), options_.trust, stop);
    if (stop.stop_requested()) {
        fs::remove_all(copy.value(), ec);
        return;
    }
    if (!installed) {
        fs::remove_all(copy.value(), ec);
        log_error(installed.error() + " (in its copy " + copy.value().string() + ")");
        ++rejections_;
        return;
    }
    const fs::path previous = current_copy(options_.state_dir);
    if (auto switched = make_current(options_.state_dir, copy.value()); !switched) {
        fs::remove_all(copy.value(), ec);
        log_error("catalogue '" + name + "' not installed: " + switched.error());
        handled_[source].outcome = Outcome::copy_failed;
        ++copy_failures_;
        return;
    }
    prune_copies(options_.state_dir, {installed.value().directory, previous});
    if (auto remembered = remember_source(options_.state_dir, kInstalledSources, fingerprint.hash);
        !remembered) {
        log_warning("catalogue '" + name + "': " + remembered.error());
    }
    installed_sources_.insert(fingerprint.hash);
    handled_[source].outcome = Outcome::installed;
    log_info("catalogue '" + name + "' installed as " + installed.value().directory.string() +
             " (" + std::to_string(installed.value().stones.size()) +
             (installed.value().stones.size() == 1 ? " stone)" : " stones)") + from);
    {
        std::lock_guard lock(mutex_);
        switch_ = std::move(installed).value();
    }
    ++installs_;
    signal_event_fd(ready_fd_);
}

void CatalogueWatcher::refuse(const fs::path& source, std::uint64_t fingerprint,
                              const std::string& why) {
    // A catalogue in the inbox is set aside there as <name>.rejected with a note saying why;
    // one on a stick or in a package's folder stays as it is and is remembered instead. Either
    // way it is reported once, not again at every start.
    std::error_code ec;
    const bool in_inbox = fs::equivalent(source.parent_path(), options_.inbox_dir, ec);
    std::string not_moved;
    if (in_inbox) {
        Result<fs::path> moved = set_aside_rejected(source, why);
        if (moved) {
            handled_.erase(source);
            seen_.erase(source);
            log_error(why + "; set aside as " + moved.value().string() + " (the reason is in " +
                      moved.value().filename().string() + ".txt beside it)");
            return;
        }
        not_moved = "; cannot set it aside (" + moved.error() + ")";
    }
    refused_sources_.insert(fingerprint);
    if (auto remembered = remember_source(options_.state_dir, kRefusedSources, fingerprint);
        !remembered) {
        log_warning("cannot remember a refused catalogue: " + remembered.error());
    }
    log_error(why + not_moved + "; not reported again until it changes");
}

}  // namespace gem::kiosk
