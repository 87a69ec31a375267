// stone_from_planes and triangulate_facets on solids whose vertices, areas and volumes are
// known by hand.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/polyhedron.hpp"
#include "geometry/validate.hpp"

namespace gem {
namespace {

FacetPlane make_plane(glm::dvec3 n, double d, std::string name = {}) {
    const double len = glm::length(n);
    return {Plane{n / len, d / len}, FacetKind::other, std::move(name)};
}

// The cube |x|, |y|, |z| <= h.
std::vector<FacetPlane> cube_planes(double h) {
    return {make_plane({1, 0, 0}, h, "+x"), make_plane({-1, 0, 0}, h, "-x"),
            make_plane({0, 1, 0}, h, "+y"), make_plane({0, -1, 0}, h, "-y"),
            make_plane({0, 0, 1}, h, "+z"), make_plane({0, 0, -1}, h, "-z")};
}

bool has_vertex(const Stone& stone, const glm::dvec3& p) {
    for (const glm::dvec3& v : stone.vertices) {
        if (glm::length(v - p) < 1e-12) return true;
    }
    return false;
}

TEST(GeometryPolyhedron, CubeFromSixPlanes) {
    auto cube = stone_from_planes(cube_planes(1.0), "cube");
    ASSERT_TRUE(cube.ok()) << cube.error();
    const Stone& s = cube.value();
    EXPECT_EQ(s.vertices.size(), 8u);
    ASSERT_EQ(s.facets.size(), 6u);
    for (const Facet& f : s.facets) EXPECT_EQ(f.loop.size(), 4u);
    EXPECT_EQ(s.facets[2].name, "+y");  // facets keep the planes' order and names
    EXPECT_EQ(s.triangles.size(), 12u);
    EXPECT_TRUE(s.convex);
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
            for (double z : {-1.0, 1.0}) EXPECT_TRUE(has_vertex(s, {x, y, z}));

    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_EQ(r.euler_characteristic, 2);
    EXPECT_NEAR(r.volume, 8.0, 1e-12);  // side 2
    EXPECT_NEAR(r.area, 24.0, 1e-12);
}

TEST(GeometryPolyhedron, RegularTetrahedron) {
    // Corners (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1); the face opposite corner c has the
    // outward normal -c/√3 and passes at 1/√3 from the centre.
    const std::vector<glm::dvec3> corners{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    std::vector<FacetPlane> planes;
    for (const glm::dvec3& c : corners) planes.push_back(make_plane(-c, 1.0));
    auto tet = stone_from_planes(planes, "tetrahedron");
    ASSERT_TRUE(tet.ok()) << tet.error();
    EXPECT_EQ(tet.value().vertices.size(), 4u);
    for (const glm::dvec3& c : corners) EXPECT_TRUE(has_vertex(tet.value(), c));
    const SolidReport r = check_solid(tet.value());
    EXPECT_TRUE(r.valid());
    // The cube of side 2 less four corner pyramids of volume (1/6)·2·2·2 each.
    EXPECT_NEAR(r.volume, 8.0 - 4.0 * 8.0 / 6.0, 1e-12);
    // Four equilateral triangles of side 2√2.
    EXPECT_NEAR(r.area, 4.0 * std::sqrt(3.0) / 4.0 * 8.0, 1e-12);
}

TEST(GeometryPolyhedron, OctahedronVolumeAndArea) {
    std::vector<FacetPlane> planes;
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
            for (double z : {-1.0, 1.0}) planes.push_back(make_plane({x, y, z}, 1.0));
    auto oct = stone_from_planes(planes, "octahedron");  // |x| + |y| + |z| <= 1
    ASSERT_TRUE(oct.ok()) << oct.error();
    EXPECT_EQ(oct.value().vertices.size(), 6u);
    EXPECT_TRUE(has_vertex(oct.value(), {0, 1, 0}));
    const SolidReport r = check_solid(oct.value());
    EXPECT_TRUE(r.valid());
    EXPECT_EQ(r.euler_characteristic, 2);
    EXPECT_NEAR(r.volume, 4.0 / 3.0, 1e-12);  // two square pyramids, base 2, height 1
    EXPECT_NEAR(r.area, 8.0 * std::sqrt(3.0) / 4.0 * 2.0, 1e-12);  // 8 triangles of side √2
}

TEST(GeometryPolyhedron, DodecahedronFromTheIcosahedronsDirections) {
    // Planes at distance 1 normal to the 12 icosahedron vertex directions (0, ±1, ±φ) and
    // cyclic permutations bound the regular dodecahedron of inradius 1.
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<FacetPlane> planes;
    for (double a : {-1.0, 1.0}) {
        for (double b : {-phi, phi}) {
            planes.push_back(make_plane({0, a, b}, glm::length(glm::dvec3(0, a, b))));
            planes.push_back(make_plane({a, b, 0}, glm::length(glm::dvec3(a, b, 0))));
            planes.push_back(make_plane({b, 0, a}, glm::length(glm::dvec3(b, 0, a))));
        }
    }
    auto dodeca = stone_from_planes(planes, "dodecahedron");
    ASSERT_TRUE(dodeca.ok()) << dodeca.error();
    EXPECT_EQ(dodeca.value().vertices.size(), 20u);
    for (const Facet& f : dodeca.value().facets) EXPECT_EQ(f.loop.size(), 5u);
    const SolidReport r = check_solid(dodeca.value());
    EXPECT_TRUE(r.valid());
    // Edge a from the inradius r = (a/2)·sqrt((25 + 11√5)/10); V = (15 + 7√5)/4 · a³.
    const double s5 = std::sqrt(5.0);
    const double a = 2.0 / std::sqrt((25.0 + 11.0 * s5) / 10.0);
    EXPECT_NEAR(r.volume, (15.0 + 7.0 * s5) / 4.0 * a * a * a, 1e-12);
}

TEST(GeometryPolyhedron, ManyPlanesThroughOnePoint) {
    // An 8-sided pyramid: 8 planes meet at the apex, like a brilliant's pointed culet.
    std::vector<FacetPlane> planes{make_plane({0, -1, 0}, 0.0, "base")};
    for (int k = 0; k < 8; ++k) {
        const double a = k * M_PI / 4.0;
        planes.push_back(make_plane({std::cos(a), 1.0, std::sin(a)}, 1.0));  // apex (0,1,0)
    }
    auto pyramid = stone_from_planes(planes, "pyramid");
    ASSERT_TRUE(pyramid.ok()) << pyramid.error();
    EXPECT_EQ(pyramid.value().vertices.size(), 9u);
    EXPECT_TRUE(has_vertex(pyramid.value(), {0, 1, 0}));
    const SolidReport r = check_solid(pyramid.value());
    EXPECT_TRUE(r.valid());
    // Base: the regular octagon with apothem 1 has area 8·tan(22.5°); height 1.
    EXPECT_NEAR(r.volume, 8.0 * std::tan(M_PI / 8.0) / 3.0, 1e-12);
}

TEST(GeometryPolyhedron, RedundantPlaneIsAnErrorNamingIt) {
    auto planes = cube_planes(1.0);
    planes.push_back(make_plane({1, 0, 0}, 5.0, "far away"));
    auto stone = stone_from_planes(planes, "cube");
    ASSERT_FALSE(stone.ok());
    EXPECT_NE(stone.error().find("far away"), std::string::npos) << stone.error();
    EXPECT_NE(stone.error().find("#6"), std::string::npos) << stone.error();
}

TEST(GeometryPolyhedron, DuplicatePlaneIsAnError) {
    auto planes = cube_planes(1.0);
    planes.push_back(make_plane({0, 1, 0}, 1.0, "second top"));
    auto stone = stone_from_planes(planes, "cube");
    ASSERT_FALSE(stone.ok());
    EXPECT_NE(stone.error().find("second top"), std::string::npos) << stone.error();
}

TEST(GeometryPolyhedron, PlaneTouchingOnlyACornerIsAnError) {
    auto planes = cube_planes(1.0);
    planes.push_back(make_plane({1, 1, 1}, 3.0, "corner"));  // touches (1,1,1) only
    auto stone = stone_from_planes(planes, "cube");
    ASSERT_FALSE(stone.ok());
    EXPECT_NE(stone.error().find("corner"), std::string::npos) << stone.error();
}

TEST(GeometryPolyhedron, UnboundedSetIsAnError) {
    auto planes = cube_planes(1.0);
    planes.erase(planes.begin() + 1);  // no -x side: a half-infinite square prism
    auto stone = stone_from_planes(planes, "prism");
    ASSERT_FALSE(stone.ok());
    EXPECT_NE(stone.error().find("finite"), std::string::npos) << stone.error();
}

TEST(GeometryPolyhedron, EmptyIntersectionIsAnError) {
    auto planes = cube_planes(1.0);
    planes.push_back(make_plane({-1, 0, 0}, -2.0, "beyond"));  // x >= 2
    auto stone = stone_from_planes(planes, "nothing");
    ASSERT_FALSE(stone.ok());
    EXPECT_NE(stone.error().find("empty"), std::string::npos) << stone.error();
}

// An L-shaped prism built by hand: the top and bottom facets are non-convex.
Stone l_prism() {
    // Outline (x, z), wound so that it is counter-clockwise seen from below (-y).
    const std::vector<glm::dvec2> outline{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    const std::uint32_t m = std::uint32_t(outline.size());
    Stone s;
    s.name = "L";
    s.convex = false;
    for (double y : {0.0, 1.0})
        for (const glm::dvec2& p : outline) s.vertices.emplace_back(p.x, y, p.y);
    Facet bottom{Plane{{0, -1, 0}, 0.0}, {}, FacetKind::pavilion, "bottom"};
    Facet top{Plane{{0, 1, 0}, 1.0}, {}, FacetKind::table, "top"};
    for (std::uint32_t i = 0; i < m; ++i) {
        bottom.loop.push_back(i);
        top.loop.push_back(2 * m - 1 - i);
    }
    s.facets = {bottom, top};
    for (std::uint32_t i = 0; i < m; ++i) {
        const std::uint32_t j = (i + 1) % m;
        const glm::dvec2 edge = outline[j] - outline[i];
        // The outline is counter-clockwise in the (x, z) plane, so outward is to the right.
        const glm::dvec3 n = glm::normalize(glm::dvec3(edge.y, 0.0, -edge.x));
        s.facets.push_back({Plane{n, glm::dot(n, s.vertices[i])},
                            {j, i, i + m, j + m},
                            FacetKind::girdle,
                            "side"});
    }
    return s;
}

TEST(GeometryPolyhedron, EarClippingTriangulatesNonConvexFacets) {
    Stone s = l_prism();
    triangulate_facets(s);
    // 6-gons give 4 triangles each, the 6 side quads 2 each.
    EXPECT_EQ(s.triangles.size(), 2u * 4u + 6u * 2u);
    for (const MeshTriangle& t : s.triangles) {
        if (t.facet != 1) continue;
        // Every top triangle lies inside the L: its centroid is not in the notch x > 1, z > 1.
        const glm::dvec3 c = (s.vertices[t.v[0]] + s.vertices[t.v[1]] + s.vertices[t.v[2]]) / 3.0;
        EXPECT_FALSE(c.x > 1.0 && c.z > 1.0);
    }
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_NEAR(r.volume, 3.0, 1e-12);          // three unit cubes
    EXPECT_NEAR(r.area, 2 * 3.0 + 8.0, 1e-12);  // top and bottom + perimeter 8 × height 1
}

}  // namespace
}  // namespace gem
