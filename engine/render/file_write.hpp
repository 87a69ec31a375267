#pragma once
// Atomic whole-file writes shared by the image writers.

#include <cstddef>
#include <filesystem>

#include "util/result.hpp"

namespace gem {

// Writes `size` bytes to a temporary file beside `path`, checks every step (a full disk shows
// at write or close) and renames it over `path`. Errors name the file and the reason.
Result<std::filesystem::path> write_file_atomic(const std::filesystem::path& path, const void* data,
                                                std::size_t size);

}  // namespace gem
