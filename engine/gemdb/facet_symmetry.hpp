#pragma once
// Facet numbers under symmetry folding (docs/gemdb-format.md, "What folding means for the
// image"): a stored view's ray-list names facets of the stone as seen in the stored view;
// for an asked direction folded by group element g, the facet seen is the image of that
// facet under g⁻¹, the facet whose plane is (g⁻¹ n, d). The table is computed once per stone.

#include <cstdint>
#include <vector>

#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem {

// perm[g][f] is the facet whose plane is g⁻¹ applied to facet f's plane, for each matrix g
// of `symmetry` (orthogonal, so g⁻¹ = gᵀ). Planes match when the normals agree within
// `normal_tolerance` (component-wise) and the offsets within `offset_tolerance_mm`. An
// error names g and f when a facet has no image, or when two facets map to one: then the
// matrices are not symmetries of the stone.
Result<std::vector<std::vector<std::uint16_t>>> facet_permutations(
    const Stone& stone, const std::vector<glm::dmat3>& symmetry, double normal_tolerance = 1e-6,
    double offset_tolerance_mm = 1e-6);

// The same for the stone's own symmetry list.
inline Result<std::vector<std::vector<std::uint16_t>>> facet_permutations(const Stone& stone) {
    return facet_permutations(stone, stone.symmetry);
}

}  // namespace gem
