// check_solid, gemmological_facet_count and symmetry_holds on a hand-built cube and on
// deliberately broken copies of it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/validate.hpp"

namespace gem {
namespace {

// The unit cube [0,1]³ written out by hand: vertex i has x from bit 0, y from bit 1, z from
// bit 2; each loop is counter-clockwise seen from outside (checked by the right-hand rule).
Stone hand_cube() {
    Stone s;
    s.name = "cube";
    for (int i = 0; i < 8; ++i) s.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    s.facets = {
        {Plane{{-1, 0, 0}, 0.0}, {0, 4, 6, 2}, FacetKind::girdle, "-x"},
        {Plane{{1, 0, 0}, 1.0}, {1, 3, 7, 5}, FacetKind::girdle, "+x"},
        {Plane{{0, -1, 0}, 0.0}, {0, 1, 5, 4}, FacetKind::pavilion, "-y"},
        {Plane{{0, 1, 0}, 1.0}, {2, 6, 7, 3}, FacetKind::table, "+y"},
        {Plane{{0, 0, -1}, 0.0}, {0, 2, 3, 1}, FacetKind::crown, "-z"},
        {Plane{{0, 0, 1}, 1.0}, {4, 5, 7, 6}, FacetKind::crown, "+z"},
    };
    for (std::uint32_t f = 0; f < 6; ++f) {
        const auto& l = s.facets[f].loop;
        s.triangles.push_back({{l[0], l[1], l[2]}, f});
        s.triangles.push_back({{l[0], l[2], l[3]}, f});
    }
    return s;
}

TEST(GeometryValidate, HandBuiltCubeIsValid) {
    const SolidReport r = check_solid(hand_cube());
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_TRUE(r.closed);
    EXPECT_TRUE(r.outward);
    EXPECT_TRUE(r.planar);
    EXPECT_EQ(r.euler_characteristic, 2);  // 8 - 12 + 6
    EXPECT_NEAR(r.volume, 1.0, 1e-15);
    EXPECT_NEAR(r.area, 6.0, 1e-15);
}

TEST(GeometryValidate, ReversedFacetIsNotClosedNorOutward) {
    Stone s = hand_cube();
    std::reverse(s.facets[3].loop.begin(), s.facets[3].loop.end());
    const SolidReport r = check_solid(s);
    EXPECT_FALSE(r.valid());
    EXPECT_FALSE(r.closed);
    EXPECT_FALSE(r.outward);
    EXPECT_TRUE(r.planar);
}

TEST(GeometryValidate, MissingFacetIsOpenWithEulerOne) {
    Stone s = hand_cube();
    s.facets.pop_back();
    s.triangles.resize(10);
    const SolidReport r = check_solid(s);
    EXPECT_FALSE(r.closed);
    EXPECT_EQ(r.euler_characteristic, 1);  // 8 - 12 + 5
    EXPECT_FALSE(r.valid());
}

TEST(GeometryValidate, VertexOffItsPlanesIsNotPlanar) {
    Stone s = hand_cube();
    s.vertices[7] += glm::dvec3(0.0, 0.01, 0.0);
    const SolidReport r = check_solid(s);
    EXPECT_FALSE(r.planar);
    EXPECT_TRUE(r.closed);
    EXPECT_FALSE(r.valid());
    // The problem names the facet and the distance, so a person can find it.
    bool named = false;
    for (const std::string& p : r.problems) named = named || p.find("(+y)") != std::string::npos;
    EXPECT_TRUE(named);
}

TEST(GeometryValidate, MissingTrianglesAreReported) {
    Stone s = hand_cube();
    s.triangles.pop_back();
    const SolidReport r = check_solid(s);
    EXPECT_FALSE(r.valid());
    EXPECT_NEAR(r.area, 5.5, 1e-15);
}

TEST(GeometryValidate, FacetCountLeavesOutGirdleFacets) {
    EXPECT_EQ(gemmological_facet_count(hand_cube()), 4);  // two of the six are "girdle"
}

TEST(GeometryValidate, SymmetryOfTheCube) {
    Stone s = hand_cube();
    for (glm::dvec3& v : s.vertices) v -= glm::dvec3(0.5);  // centre it
    const glm::dmat3 quarter_turn_y(glm::rotate(glm::dmat4(1.0), M_PI / 2.0, {0, 1, 0}));
    const glm::dmat3 mirror_x(glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1));
    s.symmetry = {glm::dmat3(1.0), quarter_turn_y, mirror_x};
    EXPECT_TRUE(symmetry_holds(s));
    s.symmetry.push_back(glm::dmat3(glm::rotate(glm::dmat4(1.0), M_PI / 6.0, {0, 1, 0})));
    EXPECT_FALSE(symmetry_holds(s));  // 30° is not a symmetry of a cube
}

TEST(GeometryValidate, FacetKindNames) {
    EXPECT_STREQ(to_string(FacetKind::table), "table");
    EXPECT_STREQ(to_string(FacetKind::crown), "crown");
    EXPECT_STREQ(to_string(FacetKind::girdle), "girdle");
    EXPECT_STREQ(to_string(FacetKind::pavilion), "pavilion");
    EXPECT_STREQ(to_string(FacetKind::culet), "culet");
    EXPECT_STREQ(to_string(FacetKind::other), "other");
}

}  // namespace
}  // namespace gem
