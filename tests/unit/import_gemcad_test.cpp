// GemCad design import: a square step written by hand (volume by hand) and the real
// Standard Round Brilliant from the GemCad user's guide (tests/data/gemcad/SRB.asc).

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
#include "picture/camera.hpp"

namespace gem {
namespace {

using import_test::contains;
using import_test::model;
using import_test::read_text;
using import_test::write_artifact;

constexpr double kDeg = std::numbers::pi / 180.0;

std::filesystem::path srb() {
    return std::filesystem::path(GEM_TEST_DATA_DIR) / "gemcad" / "SRB.asc";
}

int count_kind(const Stone& s, FacetKind kind) {
    int n = 0;
    for (const Facet& f : s.facets) n += f.kind == kind ? 1 : 0;
    return n;
}

// The square step (see the fixture's H lines): girdle prism 2x2x0.4 = 1.6; crown frustum from
// half-width 1 to 0.6 over 0.4: 0.4/3·(4 + 1.44 + √(4·1.44)); pavilion frustum from half-width 1
// to 0.2 over 0.8: 0.8/3·(4 + 0.16 + √(4·0.16)). Total 3.968.
constexpr double kSquareStepVolume =
    1.6 + 0.4 / 3.0 * (4.0 + 1.44 + 2.4) + 0.8 / 3.0 * (4.0 + 0.16 + 0.8);

TEST(ImportGemcad, SquareStepByHand) {
    auto result = load_gemcad(model("square_step.asc"));
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_EQ(s.name, "Square step test design");
    ASSERT_EQ(s.facets.size(), 14u);
    EXPECT_EQ(count_kind(s, FacetKind::girdle), 4);
    EXPECT_EQ(count_kind(s, FacetKind::crown), 4);
    EXPECT_EQ(count_kind(s, FacetKind::table), 1);
    EXPECT_EQ(count_kind(s, FacetKind::pavilion), 4);  // the fourth is on a continuation line
    EXPECT_EQ(count_kind(s, FacetKind::culet), 1);     // written "-0.000000"
    EXPECT_EQ(gemmological_facet_count(s), 10);
    EXPECT_EQ(s.vertices.size(), 16u);
    EXPECT_TRUE(s.convex);
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_NEAR(r.volume, kSquareStepVolume, 1e-9);
    EXPECT_EQ(s.symmetry.size(), 8u);  // y 4 y: four rotations and four mirrors
    EXPECT_TRUE(symmetry_holds(s));
    EXPECT_EQ(s.material.name, "GemCad design index 1.76");
    EXPECT_DOUBLE_EQ(s.material.index(), 1.76);
    for (const Facet& f : s.facets) {
        const char* expected = f.kind == FacetKind::girdle     ? "G"
                               : f.kind == FacetKind::crown    ? "C"
                               : f.kind == FacetKind::table    ? "T"
                               : f.kind == FacetKind::pavilion ? "P"
                                                               : "K";
        EXPECT_EQ(f.name, expected);
        for (std::uint32_t i : f.loop) {
            if (f.kind == FacetKind::table) {
                EXPECT_NEAR(s.vertices[i].y, 0.7, 1e-12);
            }
            if (f.kind == FacetKind::culet) {
                EXPECT_NEAR(s.vertices[i].y, -0.9, 1e-12);
            }
        }
    }
}

TEST(ImportGemcad, CuletWrittenAsZeroAngleWithNegativeDistance) {
    std::string text = read_text(model("square_step.asc"));
    text.replace(text.find("a -0.000000 0.90000000"), 22, "a 0.000000 -0.90000000");
    auto result = load_gemcad(write_artifact("culet_negative_distance.asc", text));
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(count_kind(result.value(), FacetKind::culet), 1);
    EXPECT_EQ(count_kind(result.value(), FacetKind::table), 1);
    EXPECT_NEAR(check_solid(result.value()).volume, kSquareStepVolume, 1e-9);
}

// The square step with its crown replaced by one facet at `index`, symmetry off, and the gear
// line `gear`; the crown facet's outward normal.
glm::dvec3 one_crown_facet(const std::string& gear, const std::string& index) {
    std::string text = read_text(model("square_step.asc"));
    text.replace(text.find("y 4 y"), 5, "y 1 n");
    text.replace(text.find("g 96 0.0"), 8, gear);
    text.replace(text.find("0.919238815542512 0 n C 24 48 72"), 32,
                 "0.919238815542512 " + index + " n C");
    // A file of its own per variant: CTest runs these tests at once.
    std::string name = "one_crown_facet " + gear + " at " + index + ".asc";
    std::replace(name.begin(), name.end(), ' ', '_');
    auto result = load_gemcad(write_artifact(name, text));
    EXPECT_TRUE(result.ok()) << result.error();
    if (!result.ok()) return glm::dvec3(0.0);
    EXPECT_EQ(result.value().symmetry.size(), 1u);
    for (const Facet& f : result.value().facets) {
        if (f.kind == FacetKind::crown) return f.plane.n;
    }
    ADD_FAILURE() << "no crown facet";
    return glm::dvec3(0.0);
}

// Where a crown facet's normal points in GemCad's Top View: the stone seen from above, as the
// face-up camera (picture/camera.hpp) draws it. Degrees counter-clockwise from the bottom of
// the picture.
double top_view_degrees(const glm::dvec3& n) {
    const Camera top = Camera::make(CameraSettings{}, 1.0, 64, 64).value();
    const double right = glm::dot(n, top.right()), up = glm::dot(n, top.up());
    return std::atan2(right, -up) / kDeg;  // 0 at the bottom, 90 at the right
}

TEST(ImportGemcad, APositiveGearCountsCounterClockwiseFromTheBottomOfTheTopView) {
    // GemCad's manual: index 0 at the bottom of the Top View, indices increasing counter-
    // clockwise. Index 8 of 96 is 30° round from the bottom, toward the right.
    const glm::dvec3 n = one_crown_facet("g 96 0.0", "8");
    EXPECT_NEAR(top_view_degrees(n), 30.0, 1e-9);
    EXPECT_NEAR(n.y, std::cos(45 * kDeg), 1e-12);
    // In the stone frame: azimuth 30° from +z toward +x.
    EXPECT_NEAR(n.x, std::sin(45 * kDeg) * std::sin(30 * kDeg), 1e-12);
    EXPECT_NEAR(n.z, std::sin(45 * kDeg) * std::cos(30 * kDeg), 1e-12);
}

TEST(ImportGemcad, ANegativeGearCountsClockwise) {
    EXPECT_NEAR(top_view_degrees(one_crown_facet("g -96 0.0", "8")), -30.0, 1e-9);
}

TEST(ImportGemcad, TheOffsetIsTheIndexAtTheBottom) {
    // Offset 48 of 96: index 48 at the bottom, so index 0 at the top and index 56 30° round.
    EXPECT_NEAR(std::abs(top_view_degrees(one_crown_facet("g 96 48.0", "0"))), 180.0, 1e-9);
    EXPECT_NEAR(top_view_degrees(one_crown_facet("g 96 48.0", "56")), 30.0, 1e-9);
    // GemCad 5's "g -96 48.0": indices count clockwise from 48 at the bottom, so 56 lies 30°
    // clockwise of it and 40 30° counter-clockwise.
    EXPECT_NEAR(top_view_degrees(one_crown_facet("g -96 48.0", "40")), 30.0, 1e-9);
    EXPECT_NEAR(top_view_degrees(one_crown_facet("g -96 48.0", "56")), -30.0, 1e-9);
}

TEST(ImportGemcad, TheGearLineMayLackItsLetter) {
    const glm::dvec3 lettered = one_crown_facet("g -96 48.0", "8");
    const glm::dvec3 bare = one_crown_facet("-96 48.0", "8");
    EXPECT_EQ(lettered, bare);
}

TEST(ImportGemcad, AGemCad4PinwheelKeepsItsTurnAndItsHandedness) {
    auto result = load_gemcad(model("pinwheel_gemcad4.asc"));
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_TRUE(check_solid(s).valid());
    // Four turns and no mirror: a pinwheel has a handedness.
    EXPECT_EQ(s.symmetry.size(), 4u);
    EXPECT_TRUE(symmetry_holds(s));
    // On the clockwise gear with 32 at the bottom, the crown facet at index 4 lies 28 teeth
    // counter-clockwise of the bottom: 157.5°; the girdle facet at 0, 32 teeth: the top.
    for (const Facet& f : s.facets) {
        if (f.kind == FacetKind::crown && f.name == "C" &&
            std::abs(top_view_degrees(f.plane.n) - 157.5) < 1e-9) {
            SUCCEED();
            return;
        }
    }
    ADD_FAILURE() << "no crown facet at 157.5° in the Top View";
}

TEST(ImportGemcad, BadGearLinesNameTheLineAndTheField) {
    const std::string text = read_text(model("square_step.asc"));
    struct Case {
        const char* gear;
        const char* message;
    };
    const Case cases[] = {
        {"g 0 0.0", "square_step_gear.asc:2: gear '0' is not a whole number"},
        {"g 96x 0.0", "gear '96x' is not a whole number"},
        {"g 96 west", "gear offset 'west' is not a number"},
        {"g 96 1e9", "gear offset 1e9 is not an index of the gear"},
        {"g 96 0\ng 64 0", "square_step_gear.asc:3: a second gear line"},
    };
    for (const Case& c : cases) {
        std::string bad = text;
        bad.replace(bad.find("g 96 0.0"), 8, c.gear);
        auto result = load_gemcad(write_artifact("square_step_gear.asc", bad));
        ASSERT_FALSE(result.ok()) << c.gear;
        EXPECT_TRUE(contains(result.error(), c.message)) << result.error();
    }
}

TEST(ImportGemcad, ClaimedSymmetryTheFacetsLackIsDropped) {
    // "y 4 y" claims 8 symmetries, but with a single crown facet at index 0 (azimuth 0, normal
    // in the yz plane) only the identity and the mirror x -> -x still map the stone onto
    // itself.
    std::string text = read_text(model("square_step.asc"));
    text.replace(text.find("0.919238815542512 0 n C 24 48 72"), 32, "0.919238815542512 0 n C");
    auto result = load_gemcad(write_artifact("one_crown_facet_symmetric.asc", text));
    ASSERT_TRUE(result.ok()) << result.error();
    const auto& g = result.value().symmetry;
    ASSERT_EQ(g.size(), 2u);
    EXPECT_EQ(g[0], glm::dmat3(1.0));
    const glm::dvec3 p = g[1] * glm::dvec3(0.3, 0.2, 0.5);
    EXPECT_NEAR(p.x, -0.3, 1e-12);
    EXPECT_NEAR(p.y, 0.2, 1e-12);
    EXPECT_NEAR(p.z, 0.5, 1e-12);
    EXPECT_TRUE(symmetry_holds(result.value()));
}

TEST(ImportGemcad, AnOffsetTurnsTheDesign) {
    // An offset of 12 of 96 turns the square by 45°: its girdle's corners lie on the axes,
    // √2 out.
    std::string text = read_text(model("square_step.asc"));
    text.replace(text.find("g 96 0.0"), 8, "g 96 12.0");
    auto result = load_gemcad(write_artifact("turned_square_step.asc", text));
    ASSERT_TRUE(result.ok()) << result.error();
    double max_x = 0.0;
    for (const auto& v : result.value().vertices) max_x = std::max(max_x, v.x);
    EXPECT_NEAR(max_x, std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(symmetry_holds(result.value()));  // the mirror turns with the design
}

TEST(ImportGemcad, StandardRoundBrilliantFromTheUsersGuide) {
    auto result = load_gemcad(srb());
    ASSERT_TRUE(result.ok()) << result.error();
    const Stone& s = result.value();
    EXPECT_EQ(s.name, "Standard Round Brilliant");
    EXPECT_EQ(gemmological_facet_count(s), 57);
    EXPECT_EQ(count_kind(s, FacetKind::table) + count_kind(s, FacetKind::crown), 33);
    EXPECT_EQ(count_kind(s, FacetKind::pavilion) + count_kind(s, FacetKind::culet), 24);
    EXPECT_EQ(count_kind(s, FacetKind::girdle), 16);
    EXPECT_EQ(s.symmetry.size(), 16u);
    EXPECT_TRUE(symmetry_holds(s));
    EXPECT_DOUBLE_EQ(s.material.index(), 1.54);
    EXPECT_TRUE(s.convex);
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());

    // Heights from the tier lines by hand. A crown or pavilion facet at the same index as a
    // girdle facet meets it in a horizontal edge where sin|a|·r ± cos a·y = d, r = 1.02653281:
    const double r_girdle = 1.02653281;
    const double girdle_top = (0.68444470 - std::sin(34 * kDeg) * r_girdle) / std::cos(34 * kDeg);
    const double girdle_bottom =
        (std::sin(42.5 * kDeg) * r_girdle - 0.61819401) / std::cos(42.5 * kDeg);
    const double table = 0.36450932;
    const double culet = -0.61701256 / std::cos(41.5 * kDeg);  // the eight mains meet on the axis
    double y_lo = 1e9, y_hi = -1e9, g_lo = 1e9, g_hi = -1e9;
    for (const auto& v : s.vertices) {
        y_lo = std::min(y_lo, v.y);
        y_hi = std::max(y_hi, v.y);
    }
    for (const Facet& f : s.facets) {
        if (f.kind != FacetKind::girdle) continue;
        for (std::uint32_t i : f.loop) {
            g_lo = std::min(g_lo, s.vertices[i].y);
            g_hi = std::max(g_hi, s.vertices[i].y);
        }
    }
    EXPECT_NEAR(y_hi, table, 1e-9);
    EXPECT_NEAR(y_lo, culet, 1e-9);
    EXPECT_NEAR(g_hi, girdle_top, 1e-9);
    EXPECT_NEAR(g_lo, girdle_bottom, 1e-9);
}

TEST(ImportGemcad, UnknownLineNamesFileAndLine) {
    auto result = load_gemcad(model("bad/unknown_line.asc"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "unknown_line.asc:5: unknown line 'x'")) << result.error();
}

TEST(ImportGemcad, IndicesAfterAFootnoteDoNotContinueATier) {
    // The fixture has 14 lines; the stray indices are line 15.
    const std::string text = read_text(model("square_step.asc")) + "12 24\n";
    auto result = load_gemcad(write_artifact("stray_indices.asc", text));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "stray_indices.asc:15: unknown line '12'"))
        << result.error();
}

TEST(ImportGemcad, MalformedAngleNamesLineAndToken) {
    auto result = load_gemcad(model("bad/bad_angle.asc"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "bad_angle.asc:7: tier angle '4x.0' is not a number"))
        << result.error();
}

TEST(ImportGemcad, MalformedIndexNamesLineAndToken) {
    std::string text = read_text(model("square_step.asc"));
    text.replace(text.find("0 n C 24 48 72"), 14, "0 n C 24 4B 72");
    auto result = load_gemcad(write_artifact("bad_index_token.asc", text));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "bad_index_token.asc:9: tier index '4B' is not a number"))
        << result.error();
}

TEST(ImportGemcad, NotAGemcadFileIsAnErrorOnLineOne) {
    auto result = load_gemcad(model("cube.obj"));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "cube.obj:1: not a GemCad design")) << result.error();
}

TEST(ImportGemcad, FacetThatVanishesIsAnErrorNamingTheFile) {
    // A table above the crown's apex (y = 1.3) cuts nothing away.
    std::string text = read_text(model("square_step.asc"));
    text.replace(text.find("a 0.000000 0.70000000"), 21, "a 0.000000 1.50000000");
    auto result = load_gemcad(write_artifact("vanishing_table.asc", text));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(contains(result.error(), "vanishing_table.asc: ")) << result.error();
}

}  // namespace
}  // namespace gem
