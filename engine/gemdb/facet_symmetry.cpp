#include "gemdb/facet_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "gemdb/format.hpp"

namespace gem {
namespace {

bool same_plane(const Plane& a, const glm::dvec3& n, double d, double normal_tol,
                double offset_tol) {
    return std::abs(a.n.x - n.x) <= normal_tol && std::abs(a.n.y - n.y) <= normal_tol &&
           std::abs(a.n.z - n.z) <= normal_tol && std::abs(a.d - d) <= offset_tol;
}

}  // namespace

Result<std::vector<std::vector<std::uint16_t>>> facet_permutations(
    const Stone& stone, const std::vector<glm::dmat3>& symmetry, double normal_tolerance,
    double offset_tolerance_mm) {
    const std::size_t facets = stone.facets.size();
    if (facets > gemdb::kMaxFacets)
        return Error{"facet symmetry: " + std::to_string(facets) +
                     " facets do not fit 16-bit facet numbers"};
    // Facets sorted by normal x, so each lookup scans only the facets whose x is close.
    std::vector<std::uint32_t> by_x(facets);
    for (std::uint32_t f = 0; f < facets; ++f) by_x[f] = f;
    std::sort(by_x.begin(), by_x.end(), [&](std::uint32_t a, std::uint32_t b) {
        return stone.facets[a].plane.n.x < stone.facets[b].plane.n.x;
    });

    std::vector<std::vector<std::uint16_t>> perm(symmetry.size());
    for (std::size_t g = 0; g < symmetry.size(); ++g) {
        const glm::dmat3 inverse = glm::transpose(symmetry[g]);  // orthogonal
        std::vector<std::uint16_t>& row = perm[g];
        row.resize(facets);
        std::vector<bool> taken(facets, false);
        for (std::uint32_t f = 0; f < facets; ++f) {
            const Plane& p = stone.facets[f].plane;
            const glm::dvec3 n = inverse * p.n;  // plane n·x = d maps to (g⁻¹n)·x = d
            auto it = std::lower_bound(
                by_x.begin(), by_x.end(), n.x - normal_tolerance,
                [&](std::uint32_t a, double x) { return stone.facets[a].plane.n.x < x; });
            std::int64_t found = -1;
            for (; it != by_x.end() && stone.facets[*it].plane.n.x <= n.x + normal_tolerance;
                 ++it) {
                if (same_plane(stone.facets[*it].plane, n, p.d, normal_tolerance,
                               offset_tolerance_mm)) {
                    found = *it;
                    break;
                }
            }
            if (found < 0)
                return Error{"facet symmetry: facet " + std::to_string(f) + " (" +
                             stone.facets[f].name + ") has no image under symmetry " +
                             std::to_string(g) + "; the symmetry does not hold for this stone"};
            if (taken[found])
                return Error{"facet symmetry: symmetry " + std::to_string(g) +
                             " maps two facets onto facet " + std::to_string(found)};
            taken[found] = true;
            row[f] = static_cast<std::uint16_t>(found);
        }
    }
    return perm;
}

}  // namespace gem
