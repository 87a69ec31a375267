#pragma once
// The files of a catalogue directory and their digests. A catalogue's manifest names every
// other file in it with its BLAKE2b-512 digest (RFC 7693; libsodium's crypto_generichash with
// 64 bytes out, what b2sum(1) prints), in a [blake2b] table at its end that `gemtables
// catalogue` and `gemtables seal` write:
//
//   [blake2b]
//   "stones/heart.gemdb" = "<128 hex digits>"
//
// so that a signature over the manifest (catalogue.toml.minisig, minisign's format) covers the
// whole catalogue, and staff can check a file with b2sum. The kiosk checks the digests before
// it parses any other file (kiosk/catalogue/validate.hpp). BLAKE2b rather than SHA-256: it is
// what minisign itself hashes with, and libsodium computes it 2 to 4 times as fast here
// (520-1020 against 240-256 MB/s, measured 2026-12-05), which a catalogue of 300 MB checked
// on every delivery feels.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "util/result.hpp"

namespace gem::tables {

inline constexpr const char* kManifestName = "catalogue.toml";
inline constexpr const char* kSignatureName = "catalogue.toml.minisig";
inline constexpr const char* kDigestTable = "[blake2b]";
inline constexpr std::size_t kDigestBytes = 64;  // BLAKE2b-512

// Every regular file under `dir` but the manifest and its signature, relative, '/'-separated,
// sorted. A symlink or device is an error naming it: a catalogue is copied as plain files.
Result<std::vector<std::string>> catalogue_payload(const std::filesystem::path& dir);

// The file's BLAKE2b-512 digest as 128 lowercase hex digits; errors name the file.
Result<std::string> file_digest(const std::filesystem::path& path);

// The [blake2b] table for every file of catalogue_payload(dir), ending in a newline.
Result<std::string> digest_table(const std::filesystem::path& dir);

// Rewrites dir/catalogue.toml with a fresh [blake2b] table: an old one (which must be the
// manifest's last table) is replaced, else the table is added at the end. Written atomically.
// Returns how many files it names.
Result<std::size_t> write_digests(const std::filesystem::path& dir);

// Every file under dir but the manifest and its signature is named in `digests` (relative name
// to digest hex) and matches it, and every file named is there. The error names the first
// file at fault by its relative name.
Result<bool> check_catalogue_digests(const std::filesystem::path& dir,
                                     const std::map<std::string, std::string>& digests);

// `text` as a TOML basic string, quotes and backslashes escaped (names come from staff).
std::string toml_string(const std::string& text);

// Which file names an entry of the [blake2b] table may hold: relative, inside the directory.
bool is_catalogue_file_name(const std::string& name);

}  // namespace gem::tables
