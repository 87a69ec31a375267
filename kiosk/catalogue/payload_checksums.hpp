#pragma once
// Checks the stored xxHash64 of every view's compressed payload (docs/gemdb-format.md), as the
// first part of `gemtables verify` does, but without decompressing: Database::open checks the
// header, sections and index, and only decode() checks a payload, too late for a catalogue
// that must be refused before it goes on screen.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "gemdb/reader.hpp"

namespace gem::kiosk {

// The first damaged payload as "view V level L: checksum mismatch", or nothing when every
// payload is intact. Reads the file the database was opened from, with pread(2).
std::optional<std::string> find_damaged_payload(const Database& database);

// The database at `path`, opened and every payload checked, ready to go on screen; errors name
// the file ("<path>: view 12 level 0: checksum mismatch"). For catalogues and designs' tables.
Result<std::shared_ptr<const Database>> open_intact_database(const std::filesystem::path& path);

}  // namespace gem::kiosk
