#pragma once
// The kiosk's installed catalogues under the state directory:
//   state/catalogues/<name>-<n>/   complete copies, each written whole before it gets its name
//   state/current -> catalogues/<name>-<n>   the one on screen, replaced by rename(2)
//   state/installed-sources        fingerprints of sources already installed (one hex a line)
// rename(2) replaces its target atomically (POSIX rename: "a link named new shall remain
// visible to other threads throughout the renaming operation"), so state/current always
// resolves to a complete copy, the old or the new one.

#include <cstdint>
#include <filesystem>
#include <stop_token>
#include <string>
#include <vector>

#include "catalogue/catalogue.hpp"
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

std::vector<std::uint64_t> read_installed_sources(const std::filesystem::path& state_dir);
Result<bool> remember_installed_source(const std::filesystem::path& state_dir,
                                       std::uint64_t fingerprint);

// At start: state/current if it validates, else the shipped default; a fault in the first is
// logged as a warning. The error says why neither could be used.
Result<Catalogue> load_startup_catalogue(const CatalogueOptions& options);

}  // namespace gem::kiosk
