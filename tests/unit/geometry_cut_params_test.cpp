// Cut names, customary parameters and rejection of parameters out of range.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geometry/cuts.hpp"

namespace gem {
namespace {

const CutShape kAllShapes[] = {
    CutShape::round_brilliant, CutShape::princess, CutShape::emerald, CutShape::oval,
    CutShape::marquise,        CutShape::pear,     CutShape::heart,   CutShape::cushion};

TEST(GeometryCutParams, NamesRoundTrip) {
    for (CutShape shape : kAllShapes) {
        const auto parsed = parse_cut_shape(to_string(shape));
        ASSERT_TRUE(parsed.has_value()) << to_string(shape);
        EXPECT_EQ(*parsed, shape);
    }
}

TEST(GeometryCutParams, AliasesAndCase) {
    EXPECT_EQ(parse_cut_shape("round"), CutShape::round_brilliant);
    EXPECT_EQ(parse_cut_shape("Round-Brilliant"), CutShape::round_brilliant);
    EXPECT_EQ(parse_cut_shape("navette"), CutShape::marquise);
    EXPECT_EQ(parse_cut_shape("EMERALD"), CutShape::emerald);
    EXPECT_FALSE(parse_cut_shape("trillion").has_value());
    EXPECT_FALSE(parse_cut_shape("").has_value());
}

TEST(GeometryCutParams, DefaultsAreTolkowskyAndTradeRatios) {
    const CutParams round = default_cut_params(CutShape::round_brilliant);
    EXPECT_EQ(round.table_pct, 53.0);  // Tolkowsky 1919
    EXPECT_EQ(round.crown_angle_deg, 34.5);
    EXPECT_EQ(round.pavilion_angle_deg, 40.75);
    EXPECT_EQ(round.length_to_width, 1.0);
    EXPECT_EQ(default_cut_params(CutShape::oval).length_to_width, 1.35);
    EXPECT_EQ(default_cut_params(CutShape::marquise).length_to_width, 2.0);
    EXPECT_EQ(default_cut_params(CutShape::pear).length_to_width, 1.6);
    EXPECT_EQ(default_cut_params(CutShape::emerald).length_to_width, 1.4);
    for (CutShape shape : kAllShapes) EXPECT_EQ(default_cut_params(shape).shape, shape);
}

void expect_rejected(CutParams p, const std::string& field) {
    auto stone = make_cut(p, Material{});
    ASSERT_FALSE(stone.ok()) << field;
    EXPECT_NE(stone.error().find("'" + field + "'"), std::string::npos) << stone.error();
}

TEST(GeometryCutParams, OutOfRangeNamesTheParameter) {
    const CutParams base = default_cut_params(CutShape::round_brilliant);
    CutParams p = base;
    p.width_mm = 0.0;
    expect_rejected(p, "width_mm");
    p = base;
    p.width_mm = std::numeric_limits<double>::quiet_NaN();
    expect_rejected(p, "width_mm");
    p = base;
    p.length_to_width = 1.3;  // a round is round
    expect_rejected(p, "length_to_width");
    p = base;
    p.table_pct = 90.0;
    expect_rejected(p, "table_pct");
    p = base;
    p.crown_angle_deg = 60.0;
    expect_rejected(p, "crown_angle_deg");
    p = base;
    p.pavilion_angle_deg = 25.0;
    expect_rejected(p, "pavilion_angle_deg");
    p = base;
    p.girdle_pct = -1.0;
    expect_rejected(p, "girdle_pct");
    p = base;
    p.star_pct = 100.0;
    expect_rejected(p, "star_pct");
    p = base;
    p.lower_girdle_pct = 10.0;
    expect_rejected(p, "lower_girdle_pct");
    p = base;
    p.culet_pct = 20.0;
    expect_rejected(p, "culet_pct");
    p = default_cut_params(CutShape::marquise);
    p.length_to_width = 1.0;  // a marquise needs its points
    expect_rejected(p, "length_to_width");
}

TEST(GeometryCutParams, MaterialIsKept) {
    Material m;
    m.name = "test glass";
    auto stone = make_cut(default_cut_params(CutShape::oval), m);
    ASSERT_TRUE(stone.ok()) << stone.error();
    EXPECT_EQ(stone.value().material.name, "test glass");
}

}  // namespace
}  // namespace gem
