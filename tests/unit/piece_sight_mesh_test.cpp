// The sight mesh the GPU's metal walks (piece/sight_mesh.hpp), checked record by record against
// what it was made from: every stone triangle where its placement puts it and wound outward
// (its normal away from the stone's centre, which a convex stone's every facet faces away
// from), the metal's wound as its vertex normals say, a stone's index and absorption and size
// where the layout puts them, and what a ray cannot meet left out.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/cuts.hpp"
#include "picture/camera.hpp"
#include "piece/sight_mesh.hpp"

namespace gem {
namespace {

constexpr std::size_t kFloatsPerTriangle = 24;

glm::dvec3 corner(const SightMesh& mesh, std::size_t triangle, int k) {
    const float* r = &mesh.triangles[kFloatsPerTriangle * triangle];
    const glm::dvec3 a(r[0], r[1], r[2]);
    if (k == 0) return a;
    return a + glm::dvec3(r[4 * k], r[4 * k + 1], r[4 * k + 2]);
}

TEST(SightMesh, StonesWhereTheySitWoundOutwardWithTheirMaterial) {
    Material sapphire = find_material("sapphire").value();
    sapphire.absorption_per_mm = glm::dvec3(0.5, 0.25, 0.125);
    const Stone stone = make_cut(default_cut_params(CutShape::round_brilliant), sapphire).value();
    Placement placement;
    const double a = 0.7;
    placement.rotation =
        glm::dmat3(std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a), 0, 0, 0, 1);
    placement.position = glm::dvec3(3.0, -1.0, 2.0);
    // A metal of two triangles, the second wound against its normals, and a third without
    // area; a fourth names a vertex the mesh lacks.
    MetalMesh metal;
    metal.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
    metal.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    metal.indices = {0, 1, 2, 0, 2, 1, 0, 1, 3, 0, 1, 9};
    const SightMesh mesh = sight_mesh(metal, {{&stone, placement, &sapphire}});

    ASSERT_EQ(mesh.triangle_count, 2 + stone.triangles.size());
    ASSERT_EQ(mesh.triangles.size(), kFloatsPerTriangle * mesh.triangle_count);
    int metal_seen = 0;
    std::size_t stone_seen = 0;
    for (std::size_t t = 0; t < mesh.triangle_count; ++t) {
        const float* r = &mesh.triangles[kFloatsPerTriangle * t];
        const glm::dvec3 n = glm::cross(corner(mesh, t, 1) - corner(mesh, t, 0),
                                        corner(mesh, t, 2) - corner(mesh, t, 0));
        if (r[3] == 0.0f) {
            ++metal_seen;
            EXPECT_GT(n.z, 0.0) << "a metal triangle wound against its vertex normals";
            continue;
        }
        ++stone_seen;
        EXPECT_FLOAT_EQ(r[3], static_cast<float>(sapphire.index()));
        EXPECT_FLOAT_EQ(r[15], 0.5f);
        EXPECT_FLOAT_EQ(r[19], 0.25f);
        EXPECT_FLOAT_EQ(r[23], 0.125f);
        EXPECT_GT(r[7], 0.0f);  // the stone's size
        const glm::dvec3 centroid =
            (corner(mesh, t, 0) + corner(mesh, t, 1) + corner(mesh, t, 2)) / 3.0;
        // Where the placement puts it: back in the stone's frame, inside its bounding sphere.
        EXPECT_LE(glm::length(placement.to_stone(centroid)),
                  bounding_radius(stone.vertices) + 1e-4);
        EXPECT_GT(glm::dot(n, centroid - placement.position), 0.0) << "wound inward";
    }
    EXPECT_EQ(metal_seen, 2);
    EXPECT_EQ(stone_seen, stone.triangles.size());
}

TEST(SightMesh, EveryLeafHoldsItsTrianglesAndEveryFloatIsFinite) {
    const Stone stone =
        make_cut(default_cut_params(CutShape::round_brilliant), find_material("diamond").value())
            .value();
    std::vector<PlacedStone> stones;
    for (int i = 0; i < 5; ++i) {
        Placement p;
        p.position = glm::dvec3(7.0 * i, 0.0, 0.0);
        stones.push_back({&stone, p, &stone.material});
    }
    const SightMesh mesh = sight_mesh(MetalMesh{}, stones);
    ASSERT_EQ(mesh.triangle_count, 5 * stone.triangles.size());
    for (const float f : mesh.nodes) EXPECT_TRUE(std::isfinite(f));
    for (const float f : mesh.triangles) EXPECT_TRUE(std::isfinite(f));
    std::vector<int> held(mesh.triangle_count, 0);
    const std::size_t nodes = mesh.nodes.size() / 8;
    for (std::size_t i = 0; i < nodes; ++i) {
        const float* lo = &mesh.nodes[8 * i];
        const float* hi = lo + 4;
        const auto first = static_cast<std::size_t>(lo[3]);
        const auto count = static_cast<std::size_t>(hi[3]);
        if (count == 0) {
            EXPECT_GT(first, i);
            EXPECT_LT(first, nodes);
            continue;
        }
        for (std::size_t t = first; t < first + count; ++t) {
            ASSERT_LT(t, mesh.triangle_count);
            ++held[t];
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 c = corner(mesh, t, k);
                for (int axis = 0; axis < 3; ++axis) {
                    EXPECT_LE(lo[axis], c[axis] + 1e-4);
                    EXPECT_GE(hi[axis], c[axis] - 1e-4);
                }
            }
        }
    }
    for (const int h : held) EXPECT_EQ(h, 1);
}

}  // namespace
}  // namespace gem
