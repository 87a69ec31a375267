#pragma once
// Writes the picture on screen to a PNG for CI and a shop's remote support. The file appears
// whole or not at all (written beside, then renamed), so a reader never sees half an image
// and a full disk leaves no stump behind.

#include <filesystem>

#include "gpu/render_target.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

Result<bool> write_snapshot(const gpu::RenderTarget& picture, const std::filesystem::path& file);

}  // namespace gem::kiosk
