// The round brilliant against hand calculations from its parameters.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/cuts.hpp"
#include "geometry/validate.hpp"

namespace gem {
namespace {

constexpr double kPi = 3.14159265358979323846;
double deg(double radians) {
    return radians * 180.0 / kPi;
}
double horizontal(const glm::dvec3& v) {
    return std::hypot(v.x, v.z);
}

Stone round(const CutParams& params = default_cut_params(CutShape::round_brilliant)) {
    auto stone = make_cut(params, Material{});
    EXPECT_TRUE(stone.ok()) << stone.error();
    return stone.ok() ? std::move(stone).value() : Stone{};
}

// Vertices of the facets named `name`, excluding those on the girdle (|y| <= g/2) or table.
std::vector<glm::dvec3> facet_vertices(const Stone& s, const std::string& name) {
    std::vector<glm::dvec3> out;
    for (const Facet& f : s.facets) {
        if (f.name != name) continue;
        for (std::uint32_t v : f.loop) out.push_back(s.vertices[v]);
    }
    return out;
}

TEST(GeometryRoundBrilliant, TolkowskyIsAValidSolidWith57Facets) {
    const Stone s = round();
    const SolidReport r = check_solid(s);
    EXPECT_TRUE(r.valid()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_EQ(r.euler_characteristic, 2);
    EXPECT_GT(r.volume, 0.0);
    EXPECT_TRUE(s.convex);
    // Crown 33 (table, 8 stars, 8 bezels, 16 upper girdles) + pavilion 24 (8 mains, 16 lower
    // girdles), pointed culet; girdle facets are not counted.
    EXPECT_EQ(gemmological_facet_count(s), 57);
    // 32 girdle facets when faceted: one per 11.25°.
    EXPECT_EQ(std::count_if(s.facets.begin(), s.facets.end(),
                            [](const Facet& f) { return f.kind == FacetKind::girdle; }),
              32);
    for (const Facet& f : s.facets) EXPECT_FALSE(f.name.empty());
}

TEST(GeometryRoundBrilliant, CuletMakes58) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.culet_pct = 2.0;
    const Stone s = round(p);
    EXPECT_TRUE(check_solid(s).valid());
    EXPECT_EQ(gemmological_facet_count(s), 58);  // 57 + the culet
    // The culet is an octagon 2 % of the width across flats: its vertices lie on the mains'
    // octagon at 0.065 mm from the axis across flats, i.e. 0.065 / cos(22.5°) at the corners.
    const auto culet = facet_vertices(s, "culet");
    ASSERT_EQ(culet.size(), 8u);
    for (const glm::dvec3& v : culet) {
        EXPECT_NEAR(horizontal(v), 0.02 * 6.5 / 2.0 / std::cos(kPi / 8.0), 1e-9);
    }
}

TEST(GeometryRoundBrilliant, WidthSymmetryAndGirdle) {
    const Stone s = round();
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& v : s.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    EXPECT_NEAR(hi.x - lo.x, 6.5, 1e-9);
    EXPECT_NEAR(hi.z - lo.z, 6.5, 1e-9);
    EXPECT_EQ(s.symmetry.size(), 16u);  // C8v: 8 rotations and 8 mirrors
    EXPECT_EQ(s.symmetry.front(), glm::dmat3(1.0));
    EXPECT_TRUE(symmetry_holds(s));
    // The girdle at the main facets (azimuth 0: x = R) is 2 % of 6.5 mm thick.
    double top = -INFINITY, bottom = INFINITY;
    for (const glm::dvec3& v : s.vertices) {
        if (std::abs(v.x - 3.25) < 1e-9 && std::abs(v.z) < 1e-9) {
            top = std::max(top, v.y);
            bottom = std::min(bottom, v.y);
        }
    }
    EXPECT_NEAR(top, 0.065, 1e-9);
    EXPECT_NEAR(bottom, -0.065, 1e-9);
}

TEST(GeometryRoundBrilliant, AnglesRecoveredFromFacetNormals) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    for (auto [crown, pavilion] : {std::pair{34.5, 40.75}, std::pair{30.0, 42.0}}) {
        p.crown_angle_deg = crown;
        p.pavilion_angle_deg = pavilion;
        const Stone s = round(p);
        int bezels = 0, mains = 0;
        for (const Facet& f : s.facets) {
            // A facet tilted by θ from horizontal has a normal θ away from the vertical.
            if (f.name == "bezel") {
                EXPECT_NEAR(deg(std::acos(f.plane.n.y)), crown, 1e-9);
                ++bezels;
            }
            if (f.name == "pavilion main") {
                EXPECT_NEAR(deg(std::acos(-f.plane.n.y)), pavilion, 1e-9);
                ++mains;
            }
        }
        EXPECT_EQ(bezels, 8);
        EXPECT_EQ(mains, 8);
    }
}

TEST(GeometryRoundBrilliant, TableWidthAcrossCorners) {
    const Stone s = round();
    for (const Facet& f : s.facets) {
        if (f.kind != FacetKind::table) continue;
        ASSERT_EQ(f.loop.size(), 8u);  // an octagon
        for (std::uint32_t v : f.loop)
            EXPECT_NEAR(2.0 * horizontal(s.vertices[v]), 0.53 * 6.5, 1e-9);
    }
}

TEST(GeometryRoundBrilliant, TolkowskyDepthByHand) {
    const Stone s = round();
    double top = -INFINITY, bottom = INFINITY;
    for (const glm::dvec3& v : s.vertices) {
        top = std::max(top, v.y);
        bottom = std::min(bottom, v.y);
    }
    // Crown height (1 − 0.53)/2 · tan 34.5° = 16.15 %, pavilion depth tan 40.75° / 2 = 43.08 %
    // (Tolkowsky, "Diamond Design", 1919: 16.2 % and 43.1 %), girdle 2 %: 61.23 % of 6.5 mm.
    const double crown = (1.0 - 0.53) / 2.0 * std::tan(34.5 * kPi / 180.0);
    const double pavilion = std::tan(40.75 * kPi / 180.0) / 2.0;
    EXPECT_NEAR(crown, 0.1615, 5e-4);
    EXPECT_NEAR(pavilion, 0.4308, 5e-4);
    EXPECT_NEAR(top - bottom, (crown + 0.02 + pavilion) * 6.5, 1e-9);
    EXPECT_NEAR(top - bottom, 0.6123 * 6.5, 1e-3);
}

TEST(GeometryRoundBrilliant, StarAndLowerGirdleLengths) {
    // Typical, and the two ends of the ranges where stars are shortest and longest.
    const double cases[][3] = {{53.0, 40.0, 80.0}, {70.0, 35.0, 90.0}, {45.0, 65.0, 60.0}};
    for (const auto& [table_pct, star_pct, lower_pct] : cases) {
        CutParams p = default_cut_params(CutShape::round_brilliant);
        p.table_pct = table_pct;
        p.star_pct = star_pct;
        p.lower_girdle_pct = lower_pct;
        const Stone s = round(p);
        const double r = 3.25;
        const double edge_mid = table_pct / 100.0 * r * std::cos(kPi / 8.0);
        // Star tips: the star vertices below the table, star_pct of the way from the table
        // edge's midpoint to the girdle.
        int stars = 0;
        for (const glm::dvec3& v : facet_vertices(s, "star")) {
            if (v.y < s.facets[0].plane.d - 1e-9) {
                EXPECT_NEAR(horizontal(v), edge_mid + star_pct / 100.0 * (r - edge_mid), 1e-9);
                ++stars;
            }
        }
        EXPECT_EQ(stars, 8);  // one tip per star
        // Lower girdle tips: the lower-girdle vertices below the girdle, at R·(1 − lower_pct).
        int tips = 0;
        for (const glm::dvec3& v : facet_vertices(s, "lower girdle")) {
            if (v.y < -0.065 - 1e-9) {
                EXPECT_NEAR(horizontal(v), (1.0 - lower_pct / 100.0) * r, 1e-9);
                ++tips;
            }
        }
        EXPECT_EQ(tips, 16);  // each of the 16 lower girdles has one tip vertex
    }
}

TEST(GeometryRoundBrilliant, SmoothGirdleKeepsTheCount) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.faceted_girdle = false;
    const Stone s = round(p);
    EXPECT_TRUE(check_solid(s).valid());
    EXPECT_EQ(gemmological_facet_count(s), 57);
    EXPECT_EQ(std::count_if(s.facets.begin(), s.facets.end(),
                            [](const Facet& f) { return f.kind == FacetKind::girdle; }),
              128);
    EXPECT_TRUE(symmetry_holds(s));
}

TEST(GeometryRoundBrilliant, VolumeMatchesTheTradesOneCaratAt6Point5Millimetres) {
    // The trade's rule of thumb: a well-cut 1.00 ct round diamond is about 6.4-6.5 mm across.
    // 1 ct = 200 mg at 3.515 g/cm³ (diamond) is 56.9 mm³; girdle and proportions vary, so 5 %.
    EXPECT_NEAR(check_solid(round()).volume, 200.0 / 3.515, 0.05 * 56.9);
}

TEST(GeometryRoundBrilliant, WidthScalesTheStone) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.width_mm = 1.3;  // one fifth: the volume scales by 1/125
    const double small = check_solid(round(p)).volume;
    const double big = check_solid(round()).volume;
    EXPECT_NEAR(small * 125.0, big, 1e-9 * big);
}

}  // namespace
}  // namespace gem
