#pragma once
// The two mesh compressions glTF files come in, decoded by their own libraries (Debian's
// meshoptimizer and Draco) from the bytes the file holds: no glTF library here, so the reader
// (gltf_document.cpp) keeps the file's structure and this file the codecs. Bad parameters and
// data give an Error, never reach an assertion in the codec.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.hpp"

namespace gem::import {

// EXT_meshopt_compression: one buffer view's `count` elements of `stride` bytes, from `size`
// compressed bytes, in `mode` (ATTRIBUTES, TRIANGLES, INDICES) with `filter` (NONE,
// OCTAHEDRAL, QUATERNION, EXPONENTIAL).
Result<std::vector<unsigned char>> decode_meshopt_view(const unsigned char* data, std::size_t size,
                                                       std::size_t count, std::size_t stride,
                                                       const std::string& mode,
                                                       const std::string& filter);

struct DracoMesh {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    double position_step = 0.0;  // the grid the positions were quantised to; 0 if they were not
};

// KHR_draco_mesh_compression: the mesh in `size` bytes, its positions the attribute of unique
// id `position_id`. They are taken quantised, with the quantisation Draco stored, and
// dequantised here, so that the grid's step is known (a stone's facet tolerance follows it).
Result<DracoMesh> decode_draco_mesh(const unsigned char* data, std::size_t size,
                                    std::uint32_t position_id);

}  // namespace gem::import
