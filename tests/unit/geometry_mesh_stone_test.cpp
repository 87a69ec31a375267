// stone_from_triangles on hand-built meshes whose volume, facets and convexity are known.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "geometry/polyhedron.hpp"

namespace gem {
namespace {

using Tris = std::vector<std::array<std::uint32_t, 3>>;

// Signed volume by the divergence theorem over the stone's triangles.
double mesh_volume(const Stone& s) {
    double v6 = 0.0;
    for (const auto& t : s.triangles) {
        v6 += glm::dot(s.vertices[t.v[0]], glm::cross(s.vertices[t.v[1]], s.vertices[t.v[2]]));
    }
    return v6 / 6.0;
}

// The unit cube [0,1]^3 as 12 outward (counter-clockwise) triangles over 8 corners; corner
// i has coordinates (i&1, (i>>1)&1, (i>>2)&1).
std::vector<glm::dvec3> cube_corners() {
    std::vector<glm::dvec3> c;
    for (int i = 0; i < 8; ++i) c.push_back({i & 1, (i >> 1) & 1, (i >> 2) & 1});
    return c;
}
Tris cube_triangles() {
    return {{0, 2, 1}, {1, 2, 3},   // z = 0, normal -z
            {4, 5, 6}, {5, 7, 6},   // z = 1
            {0, 1, 4}, {1, 5, 4},   // y = 0
            {2, 6, 3}, {3, 6, 7},   // y = 1
            {0, 4, 2}, {2, 4, 6},   // x = 0
            {1, 3, 5}, {3, 7, 5}};  // x = 1
}

// Every triangle with its own three copies of the corners, as STL stores them.
void unshare(std::vector<glm::dvec3>& positions, Tris& tris) {
    std::vector<glm::dvec3> out;
    for (auto& t : tris) {
        for (auto& i : t) {
            out.push_back(positions[i]);
            i = static_cast<std::uint32_t>(out.size() - 1);
        }
    }
    positions = out;
}

TEST(GeometryMeshStone, UnitCubeWeldsToEightVerticesAndSixSquareFacets) {
    auto positions = cube_corners();
    auto tris = cube_triangles();
    unshare(positions, tris);
    ASSERT_EQ(positions.size(), 36u);
    auto result = stone_from_triangles(positions, tris, "cube");
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_EQ(s.name, "cube");
    EXPECT_EQ(s.vertices.size(), 8u);
    ASSERT_EQ(s.facets.size(), 6u);
    EXPECT_EQ(s.triangles.size(), 12u);
    EXPECT_TRUE(s.convex);
    EXPECT_NEAR(mesh_volume(s), 1.0, 1e-12);
    ASSERT_EQ(s.symmetry.size(), 1u);
    int seen_axes = 0;
    for (const Facet& f : s.facets) {
        EXPECT_EQ(f.loop.size(), 4u);
        EXPECT_EQ(f.kind, FacetKind::other);
        // Each face normal is ±an axis; the outward side has d = 1 for +axis and 0 for −axis.
        for (int axis = 0; axis < 3; ++axis) {
            if (std::abs(f.plane.n[axis]) > 0.5) {
                EXPECT_NEAR(std::abs(f.plane.n[axis]), 1.0, 1e-12);
                EXPECT_NEAR(f.plane.d, f.plane.n[axis] > 0 ? 1.0 : 0.0, 1e-12);
                seen_axes |= 1 << (axis * 2 + (f.plane.n[axis] > 0 ? 1 : 0));
            }
        }
        for (std::uint32_t i : f.loop)
            EXPECT_NEAR(f.plane.signed_distance(s.vertices[i]), 0, 1e-12);
    }
    EXPECT_EQ(seen_axes, 0b111111);
    for (const MeshTriangle& t : s.triangles) {
        ASSERT_LT(t.facet, s.facets.size());
        const Plane& p = s.facets[t.facet].plane;
        const glm::dvec3 n = glm::cross(s.vertices[t.v[1]] - s.vertices[t.v[0]],
                                        s.vertices[t.v[2]] - s.vertices[t.v[0]]);
        EXPECT_GT(glm::dot(n, p.n), 0.0) << "triangle winding disagrees with its facet";
    }
}

TEST(GeometryMeshStone, FacetLoopIsCounterClockwiseSeenFromOutside) {
    auto result = stone_from_triangles(cube_corners(), cube_triangles(), "cube");
    ASSERT_TRUE(result.ok()) << result.error();
    for (const Facet& f : result.value().facets) {
        // Newell's normal of the loop points along the outward plane normal for CCW loops.
        glm::dvec3 newell{0.0};
        const auto& v = result.value().vertices;
        for (std::size_t i = 0; i < f.loop.size(); ++i) {
            newell += glm::cross(v[f.loop[i]], v[f.loop[(i + 1) % f.loop.size()]]);
        }
        EXPECT_NEAR(glm::dot(newell, f.plane.n), 2.0, 1e-12);  // twice the unit square's area
    }
}

TEST(GeometryMeshStone, InwardWoundCubeIsTurnedOutward) {
    auto tris = cube_triangles();
    for (auto& t : tris) std::swap(t[1], t[2]);
    auto result = stone_from_triangles(cube_corners(), tris, "inside-out");
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_NEAR(mesh_volume(result.value()), 1.0, 1e-12);
    for (const Facet& f : result.value().facets) {
        // Outward normals of [0,1]^3 point away from the centre (0.5, 0.5, 0.5).
        EXPECT_GT(f.plane.signed_distance({0.5, 0.5, 0.5}), -0.51);
        EXPECT_LT(f.plane.signed_distance({0.5, 0.5, 0.5}), -0.49);
    }
}

TEST(GeometryMeshStone, NearlyCoincidentCornersWeldRelativeToMeshSize) {
    auto positions = cube_corners();
    auto tris = cube_triangles();
    unshare(positions, tris);
    // Scale to 1000 mm and jitter each copy by 1e-7 mm: 1e-10 of the size, under 1e-9.
    for (std::size_t i = 0; i < positions.size(); ++i) {
        positions[i] = positions[i] * 1000.0 + glm::dvec3(1e-7 * static_cast<double>(i % 3));
    }
    auto result = stone_from_triangles(positions, tris, "cube");
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(result.value().vertices.size(), 8u);
    EXPECT_EQ(result.value().facets.size(), 6u);
    // Representatives sit up to 2e-7 mm off the true corners: 6 faces of 1e6 mm² move the
    // volume by at most ~1.2 mm³.
    EXPECT_NEAR(mesh_volume(result.value()), 1e9, 2.0);
}

TEST(GeometryMeshStone, TetrahedronHasFourTriangularFacetsAndVolumeOneSixth) {
    const std::vector<glm::dvec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const Tris t{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    auto result = stone_from_triangles(p, t, "tetra");
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(result.value().facets.size(), 4u);
    EXPECT_TRUE(result.value().convex);
    EXPECT_NEAR(mesh_volume(result.value()), 1.0 / 6.0, 1e-12);
    // The slanted face x + y + z = 1 has outward normal (1,1,1)/√3 and d = 1/√3.
    bool found = false;
    for (const Facet& f : result.value().facets) {
        if (f.plane.n.x > 0.5) {
            found = true;
            EXPECT_NEAR(f.plane.n.y, 1.0 / std::sqrt(3.0), 1e-12);
            EXPECT_NEAR(f.plane.d, 1.0 / std::sqrt(3.0), 1e-12);
        }
    }
    EXPECT_TRUE(found);
}

// An L-shaped prism: three unit squares in xy, extruded 1 along z. Volume 3, 8 facets
// (two L caps with 6 corners each, 6 sides), 12 vertices, not convex.
TEST(GeometryMeshStone, LShapedPrismIsNotConvex) {
    const std::vector<glm::dvec2> l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    std::vector<glm::dvec3> p;
    for (double z : {0.0, 1.0}) {
        for (const auto& q : l) p.push_back({q.x, q.y, z});
    }
    Tris t;
    const Tris cap{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};  // counter-clockwise from +z
    for (const auto& c : cap) {
        t.push_back({c[0] + 6, c[1] + 6, c[2] + 6});
        t.push_back({c[0], c[2], c[1]});
    }
    for (std::uint32_t i = 0; i < 6; ++i) {
        const std::uint32_t j = (i + 1) % 6;
        t.push_back({i, j, j + 6});
        t.push_back({i, j + 6, i + 6});
    }
    auto result = stone_from_triangles(p, t, "L");
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_FALSE(s.convex);
    EXPECT_EQ(s.vertices.size(), 12u);
    ASSERT_EQ(s.facets.size(), 8u);
    EXPECT_NEAR(mesh_volume(s), 3.0, 1e-12);
    int caps = 0;
    for (const Facet& f : s.facets) {
        if (std::abs(f.plane.n.z) > 0.5) {
            ++caps;
            EXPECT_EQ(f.loop.size(), 6u);
        } else {
            EXPECT_EQ(f.loop.size(), 4u);
        }
    }
    EXPECT_EQ(caps, 2);
}

TEST(GeometryMeshStone, OpenMeshIsAnErrorCountingBoundaryEdges) {
    auto tris = cube_triangles();
    tris.pop_back();  // one missing triangle leaves its three edges unmatched
    auto result = stone_from_triangles(cube_corners(), tris, "open");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().find("mesh is open: 3 boundary edges"), std::string::npos)
        << result.error();
}

TEST(GeometryMeshStone, InconsistentWindingIsAnError) {
    auto tris = cube_triangles();
    std::swap(tris[0][1], tris[0][2]);
    auto result = stone_from_triangles(cube_corners(), tris, "twisted");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().find("consistently wound"), std::string::npos) << result.error();
}

TEST(GeometryMeshStone, TriangleWithCornersInALineIsAnError) {
    auto p = cube_corners();
    p.push_back({0.5, 0.0, 0.0});  // the midpoint of the edge from corner 0 to corner 1
    auto tris = cube_triangles();
    tris.push_back({0, 8, 1});
    auto result = stone_from_triangles(p, tris, "sliver");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().find("triangle 12 has no area"), std::string::npos) << result.error();
}

TEST(GeometryMeshStone, IndexOutOfRangeAndEmptyMeshAreErrors) {
    auto tris = cube_triangles();
    tris[3][1] = 8;
    auto bad = stone_from_triangles(cube_corners(), tris, "bad");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("vertex 8 of 8"), std::string::npos) << bad.error();
    auto empty = stone_from_triangles({}, {}, "empty");
    ASSERT_FALSE(empty.ok());
    EXPECT_NE(empty.error().find("no triangles"), std::string::npos) << empty.error();
}

}  // namespace
}  // namespace gem
