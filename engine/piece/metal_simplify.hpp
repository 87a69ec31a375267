#pragma once
// A metal mesh with more triangles than the picture can show, simplified: CAD exports a shank
// as a million triangles whose chords are a thousandth of a pixel, and the metal pass then costs
// several times the stones' (docs/gltf.md). meshoptimizer's simplifier (Debian's
// libmeshoptimizer-dev) collapses edges while its estimate of how far a surface moved stays
// within `tolerance_mm` (an estimate: measured, surfaces moved up to 3.7 times that); corners
// that are left keep their normals, and a crease (corners split by normal) stays a crease.

#include <cstddef>

#include "piece/metal_mesh.hpp"

namespace gem {

// Meshes of more triangles than this are simplified by the glTF reader: the settings' own
// metal is at most some 50,000 (docs/gltf.md, bench_gltf_load).
inline constexpr std::size_t kSimplifyMetalAbove = 200000;

// Simplifies `metal` in place asking for `tolerance_mm` (kChordToleranceMm: a third of a pixel
// at the kiosk's closest view, so about a pixel as measured); returns the triangles it had.
std::size_t simplify_metal(MetalMesh& metal, double tolerance_mm);

}  // namespace gem
