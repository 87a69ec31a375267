#pragma once
// The metals a piece is made of, by the names catalogues, pieces and gemrender use, with the
// colour each reflects at normal incidence (F0) for the GPU's metal shading and the CPU
// reference alike.

#include <optional>
#include <string_view>

#include <glm/glm.hpp>

namespace gem {

enum class Metal { yellow_gold, white_gold, platinum, silver };

// "yellow_gold", "white_gold", "platinum", "silver"; nothing for any other word.
std::optional<Metal> parse_metal(std::string_view name);
const char* to_string(Metal metal);
// The names parse_metal takes, for messages: "yellow_gold, white_gold, platinum, silver".
inline constexpr const char* kMetalNames = "yellow_gold, white_gold, platinum, silver";

// Linear-RGB reflectance at normal incidence (see metal.cpp for the sources).
glm::vec3 metal_f0(Metal metal);

}  // namespace gem
