#pragma once
// The ring a catalogue stone is set in (docs/design.md, "Jewellery"): the solitaire setting
// (piece/settings.hpp) made to fit the stone, as a triangle mesh with per-vertex normals in
// the STONE frame: the stone's centre at the origin, table up +y, girdle in the xz plane. The
// finger runs along x: the shank is a circle in the yz plane below the culet, and the claws
// rise from it, bear on the girdle and bend over the crown, their tips resting on it. A ring
// of one's own is read from a Wavefront OBJ in the stone frame (piece/metal_obj.hpp).

#include "geometry/stone.hpp"
#include "piece/metal_mesh.hpp"
#include "util/result.hpp"

namespace gem {

struct RingParams {
    double inner_radius_mm = 8.5;  // the finger's radius (8.5 mm: about US size 7)
    double band_width_mm = 2.0;    // along the finger
    double band_thickness_mm = 1.6;
    int prongs = 4;               // 2..12
    double prong_width_mm = 0.0;  // 0: fitted to the stone (piece/claws.hpp)
    Metal metal = Metal::yellow_gold;
    double roughness = 0.25;  // GGX perceptual roughness, 0 (mirror) .. 1
};

// Fitted to the stone: the claws touch the girdle and their tips sit on the crown, the shank
// clears the culet. Errors name the parameter out of range.
Result<MetalMesh> make_ring(const RingParams& params, const Stone& stone);

}  // namespace gem
