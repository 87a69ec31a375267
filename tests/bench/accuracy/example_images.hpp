#pragma once
// The example pictures of docs/accuracy.md: the reference and each method side by side, with
// each method's CIEDE2000 error map (over the compared stone pixels) under it.

#include <filesystem>
#include <vector>

#include "picture/image.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

// ΔE00 full scale of the heat maps: white at 10, visible (2) is dark red.
inline constexpr float kHeatFullScale = 10.0f;

Result<bool> write_example(const std::filesystem::path& path, const Image& reference,
                           const std::vector<float>& mask, const std::vector<const Image*>& tests);

}  // namespace gem::accuracy
