#pragma once
// The ring a stone is set in (docs/design.md, "Jewellery"), as a triangle mesh with
// per-vertex normals in the STONE frame: the stone's centre at the origin, table up +y, girdle
// in the xz plane. The finger runs along x: the shank is a circle in the yz plane below the
// culet, and prongs rise from it to hold the stone at its girdle. Either made to fit a stone
// (make_ring) or read from a Wavefront OBJ already in the stone frame (piece/metal_obj.hpp).

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/stone.hpp"
#include "piece/metal_mesh.hpp"
#include "util/result.hpp"

namespace gem::gpu {

struct RingParams {
    double inner_radius_mm = 8.5;  // the finger's radius (8.5 mm: about US size 7)
    double band_width_mm = 2.0;    // along the finger
    double band_thickness_mm = 1.6;
    int prongs = 4;  // 0: a plain band under the stone
    double prong_width_mm = 0.8;
    using Metal = gem::Metal;
    Metal metal = Metal::yellow_gold;
    double roughness = 0.25;  // GGX perceptual roughness, 0 (mirror) .. 1
    int segments = 96;        // around the shank
};

// Fitted to the stone: prongs touch the girdle at its outline along their azimuths, the shank
// clears the culet. Errors name the parameter out of range.
Result<MetalMesh> make_ring(const RingParams& params, const Stone& stone);

}  // namespace gem::gpu
