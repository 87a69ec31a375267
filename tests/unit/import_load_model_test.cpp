// load_model: format detection, the move into the stone frame (centre, scale, z-up meshes),
// the material choice, and the errors every format shares.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "geometry/validate.hpp"
#include "import/load_model.hpp"
#include "import_test_files.hpp"

namespace gem {
namespace {

using import_test::contains;
using import_test::model;
using import_test::write_artifact;

constexpr double kDeg = std::numbers::pi / 180.0;

struct Box {
    glm::dvec3 lo{1e9}, hi{-1e9};
};
Box bounds(const Stone& s) {
    Box b;
    for (const auto& v : s.vertices) {
        b.lo = glm::min(b.lo, v);
        b.hi = glm::max(b.hi, v);
    }
    return b;
}

double facet_y(const Stone& s, FacetKind kind) {
    for (const Facet& f : s.facets) {
        if (f.kind == kind) return s.vertices[f.loop.front()].y;
    }
    ADD_FAILURE() << "no facet of kind " << to_string(kind);
    return 0.0;
}

void expect_valid(const Stone& s) {
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
}

TEST(ImportLoadModel, EachFormatIsRecognised) {
    for (const char* name : {"cube.obj", "tetra_ascii.stl", "cube_3ds.asc", "square_step.asc"}) {
        auto result = load_model(model(name));
        EXPECT_TRUE(result.ok()) << name << ": " << result.error();
    }
    // Content decides when the extension does not help: an OBJ saved as .txt.
    std::ifstream in(model("cube.obj"));
    std::ostringstream text;
    text << in.rdbuf();
    auto renamed = load_model(write_artifact("cube_obj.txt", text.str()));
    ASSERT_TRUE(renamed.ok()) << renamed.error();
    EXPECT_EQ(renamed.value().facets.size(), 6u);
}

TEST(ImportLoadModel, MeshIsCentredOnItsBoundingBoxAndScaledToWidth) {
    auto plain = load_model(model("cube.obj"));
    ASSERT_TRUE(plain.ok()) << plain.error();
    const Box b = bounds(plain.value());
    EXPECT_NEAR(b.lo.x, -0.5, 1e-12);
    EXPECT_NEAR(b.hi.y, 0.5, 1e-12);
    EXPECT_NEAR(b.lo.z, -0.5, 1e-12);
    EXPECT_EQ(plain.value().material.name, "crown glass");

    auto scaled = load_model(model("box_quads_negative.obj"), {.material = {}, .width_mm = 8.0});
    ASSERT_TRUE(scaled.ok()) << scaled.error();
    // The 2 x 3 x 4 box is 4 wide in xz (along z): scale 2 makes it 4 x 6 x 8, volume 192.
    const Box s = bounds(scaled.value());
    EXPECT_NEAR(s.hi.x - s.lo.x, 4.0, 1e-12);
    EXPECT_NEAR(s.hi.y - s.lo.y, 6.0, 1e-12);
    EXPECT_NEAR(s.hi.z, 4.0, 1e-12);
    EXPECT_NEAR(check_solid(scaled.value()).volume, 192.0, 1e-9);
    expect_valid(scaled.value());  // planes moved with the vertices
}

TEST(ImportLoadModel, ThreeDStudioZUpBecomesYUp) {
    // A box 2 (x) by 4 (y) by 6 (z) in 3D Studio's z-up world stands 6 tall in the stone frame.
    std::ostringstream o;
    o << "Named object: \"Tall\"\nTri-mesh, Vertices: 8 Faces: 12\nVertex list:\n";
    for (int i = 0; i < 8; ++i) {
        o << "Vertex " << i << ": X:" << 2 * (i & 1) << " Y:" << 4 * ((i >> 1) & 1)
          << " Z:" << 6 * ((i >> 2) & 1) << "\n";
    }
    const int t[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                          {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    o << "Face list:\n";
    for (int f = 0; f < 12; ++f) {
        o << "Face " << f << ": A:" << t[f][0] << " B:" << t[f][1] << " C:" << t[f][2] << "\n";
    }
    auto result = load_model(write_artifact("tall_box_3ds.asc", o.str()));
    ASSERT_TRUE(result.ok()) << result.error();
    const Box b = bounds(result.value());
    EXPECT_NEAR(b.hi.y - b.lo.y, 6.0, 1e-12);
    EXPECT_NEAR(b.hi.z - b.lo.z, 4.0, 1e-12);
    EXPECT_NEAR(b.hi.x - b.lo.x, 2.0, 1e-12);
    EXPECT_NEAR(check_solid(result.value()).volume, 48.0, 1e-9);  // still outward
    expect_valid(result.value());
}

TEST(ImportLoadModel, DesignIsCentredOnTheMiddleOfItsGirdle) {
    // The square step's girdle runs from y = -0.1 to 0.3: centre 0.1, so the table (0.7) ends
    // up at 0.6 and the culet (-0.9) at -1.0.
    auto result = load_model(model("square_step.asc"));
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_NEAR(facet_y(result.value(), FacetKind::table), 0.6, 1e-12);
    EXPECT_NEAR(facet_y(result.value(), FacetKind::culet), -1.0, 1e-12);
    EXPECT_EQ(result.value().material.name, "GemCad design index 1.76");
    expect_valid(result.value());
    EXPECT_TRUE(symmetry_holds(result.value()));

    // 4 mm wide: twice the design's 2 units, so every length doubles and the volume is 8x.
    auto wide = load_model(model("square_step.asc"), {.material = {}, .width_mm = 4.0});
    ASSERT_TRUE(wide.ok()) << wide.error();
    EXPECT_NEAR(facet_y(wide.value(), FacetKind::table), 1.2, 1e-12);
    const double volume =
        8.0 * (1.6 + 0.4 / 3.0 * (4.0 + 1.44 + 2.4) + 0.8 / 3.0 * (4.0 + 0.16 + 0.8));
    EXPECT_NEAR(check_solid(wide.value()).volume, volume, 1e-9);
    expect_valid(wide.value());
    EXPECT_TRUE(symmetry_holds(wide.value()));
}

TEST(ImportLoadModel, StandardRoundBrilliantProportions) {
    const auto path = std::filesystem::path(GEM_TEST_DATA_DIR) / "gemcad" / "SRB.asc";
    auto result = load_model(path, {.material = {}, .width_mm = 6.5});
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    // By hand from the tier lines (see ImportGemcad.StandardRoundBrilliantFromTheUsersGuide):
    // girdle edges, table and culet heights in design units.
    const double r_girdle = 1.02653281;
    const double top = (0.68444470 - std::sin(34 * kDeg) * r_girdle) / std::cos(34 * kDeg);
    const double bottom = (std::sin(42.5 * kDeg) * r_girdle - 0.61819401) / std::cos(42.5 * kDeg);
    const double centre = 0.5 * (top + bottom);
    // The 16 girdle facets put corners at index 0 and 24 (on the x and z axes), at the
    // corner radius r / cos(11.25°): that is the xz width.
    const double width = 2.0 * r_girdle / std::cos(11.25 * kDeg);
    const double scale = 6.5 / width;
    const Box b = bounds(s);
    EXPECT_NEAR(b.hi.x - b.lo.x, 6.5, 1e-9);
    EXPECT_NEAR(b.hi.y, scale * (0.36450932 - centre), 1e-9);  // table height above the girdle
    EXPECT_NEAR(b.lo.y, scale * (-0.61701256 / std::cos(41.5 * kDeg) - centre), 1e-9);
    EXPECT_NEAR(facet_y(s, FacetKind::table), b.hi.y, 1e-9);
    EXPECT_EQ(s.material.name, "GemCad design index 1.54");
    EXPECT_TRUE(symmetry_holds(s));
    expect_valid(s);
}

TEST(ImportLoadModel, MaterialOptionWins) {
    Material ruby;
    ruby.name = "test ruby";
    ruby.dispersion = Dispersion::constant_index(1.77);
    for (const char* name : {"cube.obj", "square_step.asc"}) {
        auto result = load_model(model(name), {.material = ruby, .width_mm = 0.0});
        ASSERT_TRUE(result.ok()) << result.error();
        EXPECT_EQ(result.value().material.name, "test ruby");
        EXPECT_DOUBLE_EQ(result.value().material.index(), 1.77);
    }
}

TEST(ImportLoadModel, MissingFileSaysCannotOpen) {
    const auto path = model("no_such_model.obj");
    auto result = load_model(path);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error(), path.string() + ": cannot open (No such file or directory)");
}

TEST(ImportLoadModel, EmptyFileIsAnError) {
    auto result = load_model(model("bad/empty.obj"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "empty.obj: empty file")) << result.error();
}

TEST(ImportLoadModel, UnknownFormatIsAnError) {
    auto result = load_model(write_artifact("notes.txt", "just some words\n"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "notes.txt: unknown model format")) << result.error();
}

TEST(ImportLoadModel, ReaderErrorsPassThroughWithFileAndLine) {
    auto result = load_model(model("bad/unknown_line.asc"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "unknown_line.asc:5:")) << result.error();
}

TEST(ImportLoadModel, NegativeWidthIsAnErrorNamingTheField) {
    auto result = load_model(model("cube.obj"), {.material = {}, .width_mm = -1.0});
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "width_mm")) << result.error();
}

}  // namespace
}  // namespace gem
