#pragma once
// The files of a catalogue directory and their SHA-256 digests. A catalogue's manifest names
// every other file in it with its digest, in a [sha256] table at its end that `gemtables
// catalogue` and `gemtables seal` write:
//
//   [sha256]
//   "stones/heart.gemdb" = "9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08"
//
// so that a signature over the manifest (catalogue.toml.minisig, minisign's format) covers the
// whole catalogue, and staff can check a file with sha256sum(1). The kiosk checks the
// digests before it parses any other file (kiosk/catalogue/validate.hpp).

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "util/result.hpp"

namespace gem::tables {

inline constexpr const char* kManifestName = "catalogue.toml";
inline constexpr const char* kSignatureName = "catalogue.toml.minisig";
inline constexpr const char* kDigestTable = "[sha256]";

// Every regular file under `dir` but the manifest and its signature, relative, '/'-separated,
// sorted. A symlink or device is an error naming it: a catalogue is copied as plain files.
Result<std::vector<std::string>> catalogue_payload(const std::filesystem::path& dir);

// The file's SHA-256 as 64 lowercase hex digits; errors name the file.
Result<std::string> sha256_file(const std::filesystem::path& path);

// The [sha256] table for every file of catalogue_payload(dir), ending in a newline.
Result<std::string> digest_table(const std::filesystem::path& dir);

// Rewrites dir/catalogue.toml with a fresh [sha256] table: an old one (which must be the
// manifest's last table) is replaced, else the table is added at the end. Written atomically.
// Returns how many files it names.
Result<std::size_t> write_digests(const std::filesystem::path& dir);

// Every file under dir but the manifest and its signature is named in `digests` (relative name
// to SHA-256 hex) and matches it, and every file named is there. The error names the first
// file at fault by its relative name.
Result<bool> check_catalogue_digests(const std::filesystem::path& dir,
                                     const std::map<std::string, std::string>& digests);

// `text` as a TOML basic string, quotes and backslashes escaped (names come from staff).
std::string toml_string(const std::string& text);

// Which file names an entry of the [sha256] table may hold: relative, inside the directory.
bool is_catalogue_file_name(const std::string& name);

}  // namespace gem::tables
