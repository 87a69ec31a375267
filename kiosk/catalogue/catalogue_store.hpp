#pragma once
// The kiosk's installed catalogues under the state directory:
//   state/catalogues/<name>-<n>/   complete copies, each written whole before it gets its name
//   state/current -> catalogues/<name>-<n>   the one on screen, replaced by rename(2)
//   state/installed-sources        fingerprints of sources already installed (one hex a line)
//   state/refused-sources          ... and of sources refused that could not be moved aside
// rename(2) replaces its target atomically (POSIX rename: "a link named new shall remain
// visible to other threads throughout the renaming operation"), so state/current always
// resolves to a complete copy, the old or the new one.

#include <cstdint>
#include <filesystem>
#include <stop_token>
#include <string>
#include <vector>

#include "catalogue/catalogue.hpp"
#include "catalogue/validate.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

// Copies `source` to state/catalogues/<name>-<n> (n one more than any copy there): written
// into a hidden temporary directory, every file and directory fsync'ed, then renamed. Only
// regular files and directories are copied. On any failure (ENOSPC, EFBIG, a vanished file,
// a stop request) the partial copy is removed and the error names the file and the fault.
Result<std::filesystem::path> copy_catalogue(const std::filesystem::path& source,
                                             const std::filesystem::path& state_dir,
                                             const std::string& name, std::stop_token stop = {});

// Points state/current at `copy` (a directory under state/catalogues) through a symlink made
// under a temporary name and renamed over state/current.
Result<bool> make_current(const std::filesystem::path& state_dir,
                          const std::filesystem::path& copy);

// The directory state/current resolves to, or empty when there is none.
std::filesystem::path current_copy(const std::filesystem::path& state_dir);

// Removes every entry under state/catalogues except `keep` (canonical paths: the current and
// the previous copy).
void prune_copies(const std::filesystem::path& state_dir,
                  const std::vector<std::filesystem::path>& keep);
// Removes the temporaries of copies a crash or power cut interrupted.
void remove_partial_copies(const std::filesystem::path& state_dir);

// Fingerprints of sources already dealt with, kept across restarts in state/<list>: those
// installed (kInstalledSources), and those refused where they could not be moved aside
// (kRefusedSources: a read-only stick, a package's folder). The newest 256 of each are kept.
inline constexpr const char* kInstalledSources = "installed-sources";
inline constexpr const char* kRefusedSources = "refused-sources";
std::vector<std::uint64_t> read_sources(const std::filesystem::path& state_dir, const char* list);
Result<bool> remember_source(const std::filesystem::path& state_dir, const char* list,
                             std::uint64_t fingerprint);

// A refused catalogue in the inbox is set aside there: renamed to <name>.rejected (with -2,
// -3 ... before the suffix when taken), with <name>.rejected.txt beside it saying why, so staff
// find the reason where they put the catalogue and it is reported once. The watcher does not
// look at folders so named. Renamed within the inbox because rename(2) moves a directory into
// another folder only with write permission on the directory itself (to update its ".."), and
// a clerk's copy does not give the kiosk that. The error says why it could not be renamed (the
// caller then remembers its fingerprint instead).
inline constexpr const char* kRejectedSuffix = ".rejected";
Result<std::filesystem::path> set_aside_rejected(const std::filesystem::path& source,
                                                 const std::string& reason);

// At start: state/current if it validates, else the shipped default; a fault in the first is
// logged as a warning. The error says why neither could be used. With Entries::first, each is
// validated as far as its first stone that can be shown (the kiosk's first frame waits for no
// more), and CatalogueCompletion validates it whole after.
Result<Catalogue> load_startup_catalogue(const CatalogueOptions& options,
                                         Entries entries = Entries::all, std::stop_token stop = {});

}  // namespace gem::kiosk
