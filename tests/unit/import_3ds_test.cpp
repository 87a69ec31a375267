// 3D Studio ASCII (.asc) mesh import: a 2 mm cube with spacing variations, lights and cameras.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "geometry/validate.hpp"
#include "import/load_model.hpp"
#include "import_test_files.hpp"

namespace gem {
namespace {

using import_test::contains;
using import_test::model;
using import_test::read_text;
using import_test::write_artifact;

TEST(Import3dsAscii, CubeWithSpacingVariations) {
    auto result = load_3ds_ascii(model("cube_3ds.asc"));
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_EQ(s.vertices.size(), 8u);
    EXPECT_EQ(s.facets.size(), 6u);
    EXPECT_TRUE(s.convex);
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_NEAR(r.volume, 8.0, 1e-12);  // a 2 mm cube
    EXPECT_NEAR(r.area, 24.0, 1e-12);
    // The reader keeps 3D Studio's own axes: the top face is +z at z = 2.
    bool top = false;
    for (const Facet& f : s.facets) {
        if (f.plane.n.z > 0.5) {
            top = true;
            EXPECT_NEAR(f.plane.d, 2.0, 1e-12);
        }
    }
    EXPECT_TRUE(top);
}

// A 2 mm cube object starting at x = x0, in 3D Studio's layout (corner i: x from bit 0, y from
// bit 1, z from bit 2; the same outward triangles as the fixture).
std::string cube_object(const std::string& name, double x0) {
    std::ostringstream o;
    o << "Named object: \"" << name << "\"\nTri-mesh, Vertices: 8     Faces: 12\nVertex list:\n";
    for (int i = 0; i < 8; ++i) {
        o << "Vertex " << i << ":  X:" << x0 + 2 * (i & 1) << " Y:" << 2 * ((i >> 1) & 1)
          << " Z:" << 2 * ((i >> 2) & 1) << "\n";
    }
    const int t[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                          {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    o << "Face list:\n";
    for (int f = 0; f < 12; ++f) {
        o << "Face " << f << ":  A:" << t[f][0] << " B:" << t[f][1] << " C:" << t[f][2]
          << " AB:1 BC:1 CA:1\nSmoothing: 1\n";
    }
    return o.str();
}

TEST(Import3dsAscii, SeveralObjectsAreMerged) {
    // Face indices are per object, so the second cube's must be shifted when merging.
    const std::string text = cube_object("Box01", 0.0) + "\n" + cube_object("Box02", 5.0);
    auto result = load_3ds_ascii(write_artifact("two_cubes_3ds.asc", text));
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_EQ(s.vertices.size(), 16u);
    EXPECT_EQ(s.facets.size(), 12u);
    EXPECT_FALSE(s.convex);  // two separate cubes are not one convex solid
    EXPECT_NEAR(check_solid(s).volume, 16.0, 1e-12);
    double max_x = 0.0;
    for (const auto& v : s.vertices) max_x = std::max(max_x, v.x);
    EXPECT_DOUBLE_EQ(max_x, 7.0);
}

TEST(Import3dsAscii, FaceIndexOutOfRangeNamesFileAndLine) {
    auto result = load_3ds_ascii(model("bad/bad_index_3ds.asc"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(
        contains(result.error(), "bad_index_3ds.asc:26: face index 8 out of range (8 vertices)"))
        << result.error();
}

TEST(Import3dsAscii, MissingVerticesAreAnErrorAtTheTriMeshLine) {
    std::string text = read_text(model("cube_3ds.asc"));
    text.erase(text.find("Vertex 4:"), text.find("Vertex 5:") - text.find("Vertex 4:"));
    auto result = load_3ds_ascii(write_artifact("missing_vertex_3ds.asc", text));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(
        result.error(), "missing_vertex_3ds.asc:7: Tri-mesh declares 8 vertices but 1 are missing"))
        << result.error();
}

TEST(Import3dsAscii, MalformedCoordinateNamesLineAndToken) {
    std::string text = read_text(model("cube_3ds.asc"));
    text.replace(text.find("Y:2.0 Z:0.0"), 5, "Y:2.O");
    auto result = load_3ds_ascii(write_artifact("bad_number_3ds.asc", text));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(
        contains(result.error(), "bad_number_3ds.asc:12: Y coordinate '2.O' is not a number"))
        << result.error();
}

TEST(Import3dsAscii, AbsurdCountsAreRefusedBeforeAnyAllocation) {
    std::string text = read_text(model("cube_3ds.asc"));
    const auto at = text.find("Vertices: 8");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 11, "Vertices: 4000000000");
    auto result = load_3ds_ascii(write_artifact("absurd_count_3ds.asc", text));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "absurd_count_3ds.asc:7: Tri-mesh counts"))
        << result.error();
}

}  // namespace
}  // namespace gem
