#pragma once
// What the GPU's metal and stones see of their own piece (gpu/piece_sight.hpp,
// piece_path.glsl): the metal's triangles and every stone's, where it sits, in one bounding
// volume hierarchy (trace/bvh_build.hpp), packed as float4 records for the GPU. As in the CPU
// reference (cpu/piece_tracer.cpp), a ray that meets the piece sees it and not the
// environment.
//
// Layout, four floats a record (an RGBA32F texel, gpu/texel_array.hpp):
//   node i:     texel 2i     (lo.xyz, first)   texel 2i + 1 (hi.xyz, count; 0: inner node,
//               whose left child is i + 1 and right child `first`)
//   triangle j: texel 6j     (a.xyz, 0 metal / a stone's refractive index)
//               texel 6j+1 (b - a, a stone's size: its box's diagonal), 6j+2 (c - a), wound
//               so that (b - a) × (c - a) faces outward
//               texels 6j+3 .. 6j+5: the shading normals at a, b, c (a stone's: its facet's)
//               with, in w, a stone's Beer-Lambert absorption per mm, red, green, blue

#include <cstddef>
#include <vector>

#include "geometry/stone.hpp"
#include "optics/material.hpp"
#include "piece/metal_mesh.hpp"
#include "piece/placement.hpp"

namespace gem {

// The deepest tree piece_path.glsl's fixed stack walks (its kBvhStack holds two nodes a level).
inline constexpr int kSightMeshDepth = 30;

struct PlacedStone {
    const Stone* stone = nullptr;
    Placement placement;
    const Material* material = nullptr;  // its index at the D line, its absorption
};

struct SightMesh {
    std::vector<float> nodes;      // 8 floats a node, the root first
    std::vector<float> triangles;  // 24 floats a triangle
    std::size_t triangle_count = 0;
};

// Triangles without area, or with a corner not finite or past the mesh's vertices, are left
// out (a ray cannot meet them). Every stone's material must be given.
SightMesh sight_mesh(const MetalMesh& metal, const std::vector<PlacedStone>& stones);

}  // namespace gem
