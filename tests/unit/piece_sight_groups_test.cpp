// Which stones share a virtual cube on the GPU (piece/sight_groups.hpp), on the shipped pieces:
// every stone in exactly one group; a few large stones each alone; a group
// seen from inside one of its stones (never from the metal between them); a band of 36 stones
// in a handful of groups, each of neighbours.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "piece/piece_file.hpp"
#include "piece/sight_groups.hpp"

namespace gem {
namespace {

Piece shipped(const char* name) {
    auto piece = load_piece(std::filesystem::path(GEM_CONFIG_DIR) / "pieces" / name);
    EXPECT_TRUE(piece) << (piece ? "" : piece.error());
    return piece ? piece.value() : Piece{};
}

// Whether `p` (piece frame) lies inside stone i: behind every facet plane.
bool inside(const Piece& piece, std::size_t i, const glm::dvec3& p) {
    const glm::dvec3 q = piece.stones[i].placement.to_stone(p);
    for (const Facet& f : piece.stone_of(i).facets) {
        if (glm::dot(f.plane.n, q) - f.plane.d > 0.0) return false;
    }
    return true;
}

// How far the farthest vertex of a group's stones lies from the group's centre.
double reach_mm(const Piece& piece, const SightGroup& g) {
    double reach = 0.0;
    for (const std::size_t i : g.stones) {
        for (const glm::dvec3& v : piece.stone_of(i).vertices) {
            reach = std::max(reach, glm::length(piece.stones[i].placement.to_piece(v) - g.centre));
        }
    }
    return reach;
}

void expect_a_partition(const Piece& piece, const std::vector<SightGroup>& groups) {
    std::vector<int> seen(piece.stones.size(), 0);
    for (const SightGroup& g : groups) {
        bool inside_a_member = false;
        for (const std::size_t i : g.stones) {
            ++seen.at(i);
            inside_a_member |= inside(piece, i, g.centre);
        }
        EXPECT_TRUE(inside_a_member);
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    EXPECT_LE(groups.size(), kMostSightGroups);
}

// A trilogy's side stones are smaller than its centre stone but too far apart to share.
TEST(SightGroups, ASolitaireAndATrilogyGiveEachStoneACubeOfItsOwn) {
    for (const char* name : {"solitaire.toml", "three-stone.toml", "heart-trilogy.toml"}) {
        const Piece piece = shipped(name);
        const std::vector<SightGroup> groups = sight_groups(piece);
        expect_a_partition(piece, groups);
        EXPECT_EQ(groups.size(), piece.stones.size()) << name;
        EXPECT_TRUE(groups.front().own) << name;  // the largest, the centre stone
    }
}

TEST(SightGroups, AHalosSmallStonesShareWithTheirNeighbours) {
    const Piece piece = shipped("halo.toml");
    const std::vector<SightGroup> groups = sight_groups(piece);
    expect_a_partition(piece, groups);
    // The centre stone alone; 22 small ones in a few groups of neighbours.
    ASSERT_GE(groups.size(), 3u);
    EXPECT_TRUE(groups.front().own);
    EXPECT_EQ(groups.front().stones.size(), 1u);
    for (std::size_t g = 1; g < groups.size(); ++g) {
        EXPECT_FALSE(groups[g].own);
        // Neighbours: no member farther from the group's centre than a quarter of the halo.
        EXPECT_LT(reach_mm(piece, groups[g]), 0.5 * piece.radius_mm());
    }
}

TEST(SightGroups, ABandOf36StonesNeedsAHandfulOfCubes) {
    const Piece piece = shipped("eternity-band.toml");
    ASSERT_EQ(piece.stones.size(), 36u);
    const std::vector<SightGroup> groups = sight_groups(piece);
    expect_a_partition(piece, groups);
    EXPECT_GE(groups.size(), 3u);
    for (const SightGroup& g : groups) {
        EXPECT_FALSE(g.own);
        EXPECT_LT(reach_mm(piece, g),
                  piece.radius_mm());  // an arc of neighbours, not the whole band
    }
}

}  // namespace
}  // namespace gem

namespace gem {
namespace {

// The mean of the corners of a stone's girdle facets, in the piece's frame: the middle of its
// girdle counted from the cut's own facet kinds, not from its shape.
glm::dvec3 girdle_corners_mean(const Piece& piece, std::size_t i) {
    glm::dvec3 sum(0.0);
    int n = 0;
    for (const Facet& f : piece.stone_of(i).facets) {
        if (f.kind != FacetKind::girdle) continue;
        for (const std::uint32_t v : f.loop) {
            sum += piece.stones[i].placement.to_piece(piece.stone_of(i).vertices[v]);
            ++n;
        }
    }
    EXPECT_GT(n, 0);
    return sum / static_cast<double>(n);
}

TEST(SightGroups, AStonesCubeIsSeenFromItsGirdlesMiddleWhateverFrameItsFileGaveIt) {
    Piece piece = shipped("solitaire.toml");
    ASSERT_EQ(piece.stones.size(), 1u);
    const glm::dvec3 girdle = girdle_corners_mean(piece, 0);
    EXPECT_LT(glm::length(sight_groups(piece).front().centre - girdle), 0.01);
    // The same stone in another frame: its vertices moved and turned inside it, its placement
    // moved back, so that it stands where it stood.
    const glm::dmat3 turn = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.7, glm::dvec3(1, 2, 3)));
    const glm::dvec3 shift(0.4, -1.1, 0.3);
    Stone& stone = piece.kinds[piece.stones[0].kind];
    for (glm::dvec3& v : stone.vertices) v = turn * v + shift;
    for (Facet& f : stone.facets) {
        f.plane.n = turn * f.plane.n;
        f.plane.d = glm::dot(f.plane.n, shift) + f.plane.d;
    }
    Placement& at = piece.stones[0].placement;
    at.position = at.to_piece(-glm::transpose(turn) * shift);
    at.rotation = at.rotation * glm::transpose(turn);
    EXPECT_LT(glm::length(girdle_corners_mean(piece, 0) - girdle), 1e-9);
    EXPECT_LT(glm::length(sight_groups(piece).front().centre - girdle), 0.01);
}

}  // namespace
}  // namespace gem
