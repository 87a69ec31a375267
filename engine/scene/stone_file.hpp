#pragma once
// A stone description, as gemtables builds from and catalogues and pieces name: a small TOML file
// with a [stone] table (a cut and its proportions, or a model file) and a [material] table, read
// with the engine's scene reader so the keys mean exactly what they mean in a scene
// (config/stones/README.md).

#include <filesystem>

#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem {

// Errors name the file, the line and the key ("ruby.toml:4: stone.crown_angle_deg: ...").
Result<Stone> load_stone_file(const std::filesystem::path& path);

}  // namespace gem
