// The material catalogue and dispersion formulas against published gemmological figures.
// Sources of the expected values: GIA Gem Reference Guide (1995) for n_D and the B–G
// dispersion n(G) − n(B); Nassau et al., Gems & Gemology 33(4), 1997 for moissanite;
// Schott's N-BK7 datasheet for crown glass.

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "optics/material.hpp"

namespace gem {
namespace {

double dispersion_bg(const Material& m) {
    return m.index(kFraunhoferG) - m.index(kFraunhoferB);
}

TEST(OpticsMaterial, ConstantIndexIsFlat) {
    const Dispersion d = Dispersion::constant_index(1.9);
    for (double nm : {380.0, 500.0, 730.0}) EXPECT_EQ(d.index(nm), 1.9);
}

TEST(OpticsMaterial, CauchyFitReproducesIndexAndDispersion) {
    const double cases[][2] = {{2.417, 0.044}, {1.762, 0.018}, {2.648, 0.104}, {1.5, 0.0}};
    for (const auto& [nd, bg] : cases) {
        const Dispersion d = Dispersion::cauchy_from_nd(nd, bg);
        EXPECT_EQ(d.kind, Dispersion::Kind::cauchy);
        EXPECT_NEAR(d.index(kFraunhoferD), nd, 1e-12);
        EXPECT_NEAR(d.index(kFraunhoferG) - d.index(kFraunhoferB), bg, 1e-12);
    }
}

TEST(OpticsMaterial, CauchyFormulaByHand) {
    // n = A + B/λ² with A = 1.5, B = 0.01 µm²: at 500 nm n = 1.5 + 0.01/0.25 = 1.54.
    Dispersion d;
    d.kind = Dispersion::Kind::cauchy;
    d.coef = {1.5, 0.01};
    EXPECT_NEAR(d.index(500.0), 1.54, 1e-12);
    EXPECT_NEAR(d.index(1000.0), 1.51, 1e-12);
}

TEST(OpticsMaterial, SellmeierFormulaByHand) {
    // One term, n² = 1 + λ²/(λ² − 0.01) with λ = 0.2 µm: 1 + 0.04/0.03 = 7/3.
    Dispersion d;
    d.kind = Dispersion::Kind::sellmeier;
    d.coef = {1.0, 0.01, 0.0, 0.0, 0.0, 0.0};
    EXPECT_NEAR(d.index(200.0), std::sqrt(7.0 / 3.0), 1e-12);
}

TEST(OpticsMaterial, DiamondSellmeierGivesPublishedFigures) {
    const std::optional<Material> diamond = find_material("diamond");
    ASSERT_TRUE(diamond.has_value());
    EXPECT_EQ(diamond->dispersion.kind, Dispersion::Kind::sellmeier);
    // GIA: n_D 2.417, dispersion 0.044, both quoted to three decimals; the tolerances allow
    // the rounding of the published figures plus one unit of their last digit.
    EXPECT_NEAR(diamond->index(kFraunhoferD), 2.417, 1e-3);
    EXPECT_NEAR(dispersion_bg(*diamond), 0.044, 1e-3);
}

TEST(OpticsMaterial, CrownGlassMatchesSchottDatasheet) {
    // Schott N-BK7: n_d (587.56 nm) = 1.51680, n_F (486.13) = 1.52238, n_C (656.27) = 1.51432,
    // all given to 5 decimals.
    const std::optional<Material> bk7 = find_material("bk7");
    ASSERT_TRUE(bk7.has_value());
    EXPECT_NEAR(bk7->index(587.56), 1.51680, 2e-5);
    EXPECT_NEAR(bk7->index(486.13), 1.52238, 2e-5);
    EXPECT_NEAR(bk7->index(656.27), 1.51432, 2e-5);
}

struct Published {
    const char* name;
    double nd_min, nd_max;  // published range of n_D
    double bg;              // published dispersion n(G) − n(B)
    double bg_tolerance;    // its last digit, or the published spread
    bool coloured;
};

// GIA Gem Reference Guide unless noted. Ranges are the usual RI range for the species.
const Published kPublished[] = {
    {"diamond", 2.416, 2.419, 0.044, 0.001, false},
    {"sapphire", 1.762, 1.770, 0.018, 0.001, true},
    {"ruby", 1.762, 1.770, 0.018, 0.001, true},
    {"emerald", 1.577, 1.583, 0.014, 0.001, true},
    {"garnet", 1.760, 1.820, 0.024, 0.001, true},           // almandine, 1.790 ± 0.030
    {"spinel", 1.710, 1.735, 0.020, 0.001, true},           // 1.718 +0.017/−0.008
    {"cubic zirconia", 2.150, 2.180, 0.062, 0.004, false},  // dispersion 0.058–0.066
    {"moissanite", 2.648, 2.691, 0.104, 0.001, false},      // Nassau et al. 1997, ω to ε
    {"quartz", 1.544, 1.553, 0.013, 0.001, false},
    {"crown glass", 1.5160, 1.5175, 0.0138, 0.0005, false},  // Schott N-BK7, n_d 1.5168
};

TEST(OpticsMaterial, EveryBuiltinMatchesPublishedFigures) {
    const std::vector<Material>& all = builtin_materials();
    EXPECT_EQ(all.size(), std::size(kPublished));
    for (const Published& p : kPublished) {
        SCOPED_TRACE(p.name);
        const auto it = std::find_if(all.begin(), all.end(),
                                     [&](const Material& m) { return m.name == p.name; });
        ASSERT_NE(it, all.end());
        const Material& m = *it;
        const double nd = m.index(kFraunhoferD);
        EXPECT_GE(nd, p.nd_min);
        EXPECT_LE(nd, p.nd_max);
        EXPECT_GT(dispersion_bg(m), 0.0);
        EXPECT_NEAR(dispersion_bg(m), p.bg, p.bg_tolerance);
        // Normal dispersion: the index falls steadily from violet to red.
        for (double nm = 380.0; nm < 730.0; nm += 10.0) EXPECT_GT(m.index(nm), m.index(nm + 10.0));

        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(m.body_colour[c], 0.0);
            EXPECT_LE(m.body_colour[c], 1.0);
            EXPECT_GE(m.absorption_per_mm[c], 0.0);
            EXPECT_LT(m.absorption_per_mm[c], 10.0);  // a stone a few mm across still shows
        }
        if (p.coloured) {
            EXPECT_GT(glm::length(m.absorption_per_mm), 0.0);
        } else {
            EXPECT_EQ(m.body_colour, glm::dvec3(1.0));
            EXPECT_EQ(m.absorption_per_mm, glm::dvec3(0.0));
        }
    }
}

// Index of the channel that absorbs least, i.e. the hue that gets through.
int clearest_channel(const Material& m) {
    const glm::dvec3 a = m.absorption_per_mm;
    return a.x <= a.y && a.x <= a.z ? 0 : (a.y <= a.z ? 1 : 2);
}

TEST(OpticsMaterial, ColouredStonesHaveTheirHue) {
    // Ruby, almandine and red spinel are red, blue sapphire blue, emerald green.
    const std::pair<const char*, int> hues[] = {
        {"ruby", 0}, {"garnet", 0}, {"spinel", 0}, {"sapphire", 2}, {"emerald", 1}};
    for (const auto& [name, channel] : hues) {
        const std::optional<Material> m = find_material(name);
        ASSERT_TRUE(m.has_value()) << name;
        EXPECT_EQ(clearest_channel(*m), channel) << name;
        EXPECT_EQ(m->body_colour[channel], 1.0) << name;
    }
}

TEST(OpticsMaterial, FindMaterialAcceptsAliasesAnyCase) {
    const std::pair<const char*, const char*> lookups[] = {
        {"Diamond", "diamond"},
        {"RUBY", "ruby"},
        {"cz", "cubic zirconia"},
        {"CZ", "cubic zirconia"},
        {"cubic-zirconia", "cubic zirconia"},
        {"Cubic Zirconia", "cubic zirconia"},
        {"cubic_zirconia", "cubic zirconia"},
        {"bk7", "crown glass"},
        {"N-BK7", "crown glass"},
        {"crown-glass", "crown glass"},
        {"almandine", "garnet"},
        {"Moissanite", "moissanite"},
    };
    for (const auto& [query, expected] : lookups) {
        const std::optional<Material> m = find_material(query);
        ASSERT_TRUE(m.has_value()) << query;
        EXPECT_EQ(m->name, expected) << query;
    }
    EXPECT_FALSE(find_material("unobtainium").has_value());
    EXPECT_FALSE(find_material("").has_value());
    EXPECT_FALSE(find_material("diamonds").has_value());
}

TEST(OpticsMaterial, BuiltinsArePhysicalAndBrokenDispersionsAreNot) {
    for (const Material& m : builtin_materials()) EXPECT_TRUE(m.dispersion.is_physical()) << m.name;
    EXPECT_FALSE(Dispersion::constant_index(0.8).is_physical());  // n < 1
    // A Sellmeier resonance at 500 nm (C = 0.25 µm²) lies inside the rendered spectrum.
    Dispersion resonant;
    resonant.kind = Dispersion::Kind::sellmeier;
    resonant.coef = {1.0, 0.25};
    EXPECT_FALSE(resonant.is_physical());
    resonant.coef = {1.0, 0.01};  // resonance at 100 nm, outside
    EXPECT_TRUE(resonant.is_physical());
}

}  // namespace
}  // namespace gem
