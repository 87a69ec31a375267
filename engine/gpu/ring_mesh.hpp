#pragma once
// The ring a stone is set in (DESIGN.md, "The method", 3. Jewellery), as a triangle mesh with
// per-vertex normals in the STONE frame: the stone's centre at the origin, table up +y, girdle
// in the xz plane. The finger runs along x: the shank is a circle in the yz plane below the
// culet, and prongs rise from it to hold the stone at its girdle. Either made to fit a stone
// (make_ring) or read from a Wavefront OBJ already in the stone frame (load_ring_obj).

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem::gpu {

struct RingParams {
    double inner_radius_mm = 8.5;  // the finger's radius (8.5 mm: about US size 7)
    double band_width_mm = 2.0;    // along the finger
    double band_thickness_mm = 1.6;
    int prongs = 4;  // 0: a plain band under the stone
    double prong_width_mm = 0.8;
    enum class Metal { yellow_gold, white_gold, platinum, silver } metal = Metal::yellow_gold;
    double roughness = 0.25;  // GGX perceptual roughness, 0 (mirror) .. 1
    int segments = 96;        // around the shank
};

struct RingMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // unit, outward
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
    glm::vec3 f0{1.0f};                  // normal-incidence reflectance, linear RGB
    float roughness = 0.25f;

    // Radius of the sphere about the stone's centre that holds the ring.
    double radius_mm() const;
};

// Linear-RGB reflectance at normal incidence of each metal (see ring_mesh.cpp for sources).
glm::vec3 metal_f0(RingParams::Metal metal);

// Fitted to the stone: prongs touch the girdle at its outline along their azimuths, the shank
// clears the culet. Errors name the parameter out of range.
Result<RingMesh> make_ring(const RingParams& params, const Stone& stone);

// v, vn and f statements (f: v, v/vt, v//vn, v/vt/vn; polygons fanned); vertex normals
// are taken from vn or, without them, averaged from the faces around each vertex. The file's
// units are millimetres and its frame the stone frame. Errors name the file and the line.
Result<RingMesh> load_ring_obj(const std::filesystem::path& path, RingParams::Metal metal,
                               double roughness);

}  // namespace gem::gpu
