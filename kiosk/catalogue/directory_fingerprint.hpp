#pragma once
// One number that changes whenever anything in a directory tree changes the way a copy in
// progress changes it: a name appears or goes, a size or a modification time changes. The
// watcher waits for it to stay the same for the settle time, and remembers it for directories
// it rejected so that an unchanged one is not validated again. The status-change time is in it
// too: dpkg gives a package's files the modification times they had when it was built, so a
// downgrade back to a version shown before changes only that (rename(2) and a new file set it).
// Reading never changes it.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "util/result.hpp"

namespace gem::kiosk {

struct DirectoryFingerprint {
    std::uint64_t hash = 0;  // xxHash64 of every entry's relative name, type, size, mtime, ctime
    std::uint64_t files = 0;
    std::uint64_t bytes = 0;
    std::vector<std::filesystem::path> directories;  // the tree's directories, for watches
    // dpkg is unpacking into it: a file named *.dpkg-new or *.dpkg-tmp (dpkg unpacks each file
    // under such a name and renames it into place), so it is not settled whatever the time.
    bool unpacking = false;
    bool operator==(const DirectoryFingerprint& other) const { return hash == other.hash; }
};

// Walks `dir` without following symlinks. Errors name the entry that cannot be read.
Result<DirectoryFingerprint> fingerprint_directory(const std::filesystem::path& dir);

}  // namespace gem::kiosk
