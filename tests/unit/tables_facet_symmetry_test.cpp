// Facet numbers under symmetry folding: for each element g of a round brilliant's symmetry
// group, perm[g] is a permutation of the facets, the identity for g = identity, and facet
// perm[g][f] is where g⁻¹ carries facet f, checked on the geometry itself by mapping the
// vertices of facet f's loop and finding them on the mapped facet (its plane and its loop).

#include <gtest/gtest.h>

#include <cmath>

#include <glm/glm.hpp>

#include "gemdb/facet_symmetry.hpp"
#include "geometry/cuts.hpp"

namespace gem {
namespace {

Stone round_brilliant() {
    auto stone = make_cut(default_cut_params(CutShape::round_brilliant), Material{});
    EXPECT_TRUE(stone.ok()) << stone.error();
    return std::move(stone).value();
}

TEST(TablesFacetSymmetry, RoundBrilliantRowsArePermutations) {
    const Stone stone = round_brilliant();
    ASSERT_EQ(stone.symmetry.size(), 16u);
    auto perm = facet_permutations(stone);
    ASSERT_TRUE(perm.ok()) << perm.error();
    const std::size_t facets = stone.facets.size();
    ASSERT_EQ(perm.value().size(), stone.symmetry.size());
    for (std::size_t g = 0; g < perm.value().size(); ++g) {
        const auto& row = perm.value()[g];
        ASSERT_EQ(row.size(), facets);
        std::vector<int> hits(facets, 0);
        for (std::uint16_t f : row) {
            ASSERT_LT(f, facets);
            ++hits[f];
        }
        for (std::size_t f = 0; f < facets; ++f) EXPECT_EQ(hits[f], 1) << "g " << g << " f " << f;
    }
    for (std::size_t f = 0; f < facets; ++f) EXPECT_EQ(perm.value()[0][f], f);
    // A non-trivial group moves some facet.
    bool moved = false;
    for (std::size_t g = 1; g < perm.value().size(); ++g) {
        for (std::size_t f = 0; f < facets; ++f) moved |= perm.value()[g][f] != f;
    }
    EXPECT_TRUE(moved);
}

TEST(TablesFacetSymmetry, MappedFacetHoldsTheMappedLoop) {
    const Stone stone = round_brilliant();
    auto perm = facet_permutations(stone);
    ASSERT_TRUE(perm.ok()) << perm.error();
    constexpr double kTol = 1e-9;
    for (std::size_t g = 0; g < stone.symmetry.size(); ++g) {
        const glm::dmat3 inverse = glm::inverse(stone.symmetry[g]);
        for (std::size_t f = 0; f < stone.facets.size(); ++f) {
            const Facet& image = stone.facets[perm.value()[g][f]];
            const Facet& source = stone.facets[f];
            ASSERT_GE(source.loop.size(), 3u);
            EXPECT_EQ(image.loop.size(), source.loop.size()) << "g " << g << " f " << f;
            for (std::uint32_t v : source.loop) {
                const glm::dvec3 p = inverse * stone.vertices[v];
                EXPECT_NEAR(image.plane.signed_distance(p), 0.0, kTol) << "g " << g << " f " << f;
                bool on_loop = false;
                for (std::uint32_t w : image.loop) {
                    on_loop |= glm::length(stone.vertices[w] - p) < kTol;
                }
                EXPECT_TRUE(on_loop) << "g " << g << " f " << f << " vertex " << v;
            }
            // The mapped normal is the image facet's outward normal.
            EXPECT_GT(glm::dot(image.plane.n, inverse * source.plane.n), 1.0 - 1e-9);
        }
    }
}

TEST(TablesFacetSymmetry, BrokenSymmetryIsAnError) {
    const Stone stone = round_brilliant();
    // A rotation by 10° about the axis is no symmetry of an 8-fold stone.
    const double a = 10.0 * 3.14159265358979323846 / 180.0;
    const glm::dmat3 turn(std::cos(a), 0.0, -std::sin(a), 0.0, 1.0, 0.0, std::sin(a), 0.0,
                          std::cos(a));
    auto perm = facet_permutations(stone, {glm::dmat3(1.0), turn});
    ASSERT_FALSE(perm.ok());
    EXPECT_NE(perm.error().find("no image under symmetry 1"), std::string::npos) << perm.error();
}

}  // namespace
}  // namespace gem
