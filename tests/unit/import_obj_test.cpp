// Wavefront OBJ import: hand-written fixtures whose volume, facets and convexity are known.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "geometry/validate.hpp"
#include "import/load_model.hpp"
#include "import_test_files.hpp"

namespace gem {
namespace {

using import_test::contains;
using import_test::model;

// The facet whose outward normal is closest to `axis`.
const Facet& facet_along(const Stone& s, const glm::dvec3& axis) {
    const Facet* best = &s.facets.front();
    for (const Facet& f : s.facets) {
        if (glm::dot(f.plane.n, axis) > glm::dot(best->plane.n, axis)) best = &f;
    }
    return *best;
}

TEST(ImportObj, UnitCubeHasSixFacetsEightVerticesAndVolumeOne) {
    auto result = load_obj(model("cube.obj"));
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_EQ(s.name, "cube");
    EXPECT_EQ(s.vertices.size(), 8u);
    EXPECT_EQ(s.facets.size(), 6u);
    EXPECT_EQ(s.triangles.size(), 12u);
    EXPECT_TRUE(s.convex);
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_NEAR(r.volume, 1.0, 1e-12);
    EXPECT_NEAR(r.area, 6.0, 1e-12);
    EXPECT_EQ(s.material.name, "crown glass");
    EXPECT_DOUBLE_EQ(s.material.index(), 1.5168);
}

TEST(ImportObj, QuadsWithNegativeIndicesMakeTheBox) {
    auto result = load_obj(model("box_quads_negative.obj"));
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_EQ(s.vertices.size(), 8u);
    ASSERT_EQ(s.facets.size(), 6u);
    EXPECT_TRUE(s.convex);
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_NEAR(r.volume, 2.0 * 3.0 * 4.0, 1e-12);
    EXPECT_NEAR(r.area, 2.0 * (2 * 3 + 3 * 4 + 2 * 4), 1e-12);
    // The box is [0,2]x[0,3]x[0,4]: the +x, +y, +z faces sit at 2, 3, 4; the others at 0.
    EXPECT_NEAR(facet_along(s, {1, 0, 0}).plane.d, 2.0, 1e-12);
    EXPECT_NEAR(facet_along(s, {0, 1, 0}).plane.d, 3.0, 1e-12);
    EXPECT_NEAR(facet_along(s, {0, 0, 1}).plane.d, 4.0, 1e-12);
    EXPECT_NEAR(facet_along(s, {-1, 0, 0}).plane.d, 0.0, 1e-12);
    for (const Facet& f : s.facets) EXPECT_EQ(f.loop.size(), 4u);
}

TEST(ImportObj, LShapedPrismIsNotConvex) {
    auto result = load_obj(model("l_prism.obj"));
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_FALSE(s.convex);
    EXPECT_EQ(s.vertices.size(), 12u);
    EXPECT_EQ(s.facets.size(), 8u);
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_NEAR(r.volume, 3.0, 1e-12);
    // Two L caps of area 3 and a perimeter of 8 at height 1.
    EXPECT_NEAR(r.area, 2 * 3.0 + 8.0, 1e-12);
    EXPECT_EQ(facet_along(s, {0, 0, 1}).loop.size(), 6u);
}

TEST(ImportObj, IndexOutOfRangeNamesFileAndLine) {
    auto result = load_obj(model("bad/bad_index.obj"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(
        contains(result.error(), "bad_index.obj:11: face index 9 out of range (8 vertices)"))
        << result.error();
}

TEST(ImportObj, NegativeIndexBeforeItsVertexIsAnError) {
    const auto path = std::filesystem::path(GEM_ARTIFACT_DIR) / "import" / "negative_early.obj";
    std::filesystem::create_directories(path.parent_path());
    {
        std::FILE* f = std::fopen(path.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fputs("v 0 0 0\nv 1 0 0\nf -1 -2 -3\n", f);
        std::fclose(f);
    }
    auto result = load_obj(path);
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "negative_early.obj:3: face index -3 out of range"))
        << result.error();
}

TEST(ImportObj, MalformedNumberNamesFileLineAndToken) {
    auto result = load_obj(model("bad/bad_number.obj"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(
        contains(result.error(), "bad_number.obj:3: vertex coordinate '1x' is not a number"))
        << result.error();
}

TEST(ImportObj, OpenMeshIsAnError) {
    auto result = load_obj(model("bad/open.obj"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "open.obj: mesh is open: 3 boundary edges"))
        << result.error();
}

TEST(ImportObj, EmptyFileIsAnError) {
    auto result = load_obj(model("bad/empty.obj"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "empty.obj: no triangles")) << result.error();
}

TEST(ImportObj, NonConvexPolygonFacesAreTriangulatedWithoutFolding) {
    // Star prism, outer radius R = 2, inner r = 1, height 1: each cap is 10 triangles of
    // area R·r·sin 36° / 2, each side edge sqrt(R² + r² − 2Rr cos 36°) long.
    auto result = load_obj(model("star_prism.obj"));
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    const double pi = 3.14159265358979323846;
    const double cap = 5.0 * 2.0 * 1.0 * std::sin(pi / 5.0);
    const double edge = std::sqrt(4.0 + 1.0 - 4.0 * std::cos(pi / 5.0));
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_NEAR(r.volume, cap * 1.0, 1e-9);
    EXPECT_NEAR(r.area, 2.0 * cap + 10.0 * edge * 1.0, 1e-9);
    EXPECT_EQ(s.facets.size(), 12u);  // two caps and ten sides
    EXPECT_FALSE(s.convex);
    for (const Facet& f : s.facets) {
        // Every facet's outward normal points away from the prism's axis or along ±z.
        const glm::dvec3 c = s.vertices[f.loop.front()];
        if (std::abs(f.plane.n.z) > 0.5) {
            EXPECT_GT(f.plane.n.z * (c.z - 0.5), 0.0);
        }
    }
}

}  // namespace
}  // namespace gem
