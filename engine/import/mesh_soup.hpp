#pragma once
// Private: the triangle soup a mesh reader collects, turned into a Stone with errors that
// name the file.

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem::import {

struct TriangleSoup {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// The stone is named after the file's stem and made of crown glass; `weld_tolerance` is
// relative to the mesh size.
Result<Stone> stone_from_soup(const std::filesystem::path& path, const TriangleSoup& soup,
                              double weld_tolerance = 1e-9);

}  // namespace gem::import
