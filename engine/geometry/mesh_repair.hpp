#pragma once
// Repairs for triangle meshes as CAD tools export them, before they become stones
// (stone_from_triangles wants a closed, consistently wound mesh without slivers). Each works on
// welded indices (a corner shared by its triangles is one index) and says what it changed, so
// the reader can report it in one line.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.hpp"

namespace gem {

using MeshTriangles = std::vector<std::array<std::uint32_t, 3>>;

// Triangles with no area, dropped. One whose corners are distinct but in a line is a T-junction
// seen from the other side: the neighbour across its long edge is split at the middle corner,
// so the mesh stays closed. One with a repeated corner only goes. "No area": its height over
// its longest edge is below relative × size, size the mesh's extent (the rounding of the
// file's corners, which leaves a T-junction's sliver a hair's breadth off its line). Returns
// how many were dropped.
std::size_t drop_zero_area_triangles(const std::vector<glm::dvec3>& positions,
                                     MeshTriangles& triangles, double relative = 1e-6);

// Every triangle wound as its neighbours are (a CAD export that flipped a few), starting from
// the first triangle of each connected part. Returns how many were turned; an error when an
// edge has more than two triangles (not a surface) or a part cannot be wound one way (a
// Möbius strip).
Result<std::size_t> orient_consistently(MeshTriangles& triangles);

// Each hole (a loop of edges with a triangle on one side only) closed by triangles across it,
// ear-clipped in the plane the loop faces, wound as the triangles around it. Returns how many
// holes were filled; an error when the edges with one side do not form simple loops.
Result<std::size_t> fill_holes(const std::vector<glm::dvec3>& positions, MeshTriangles& triangles);

}  // namespace gem
