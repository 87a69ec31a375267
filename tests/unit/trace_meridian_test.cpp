// The classic meridian test of a round brilliant (Tolkowsky, "Diamond Design", 1919): light
// entering the table straight down, in the meridian plane of a pavilion main, meets that main
// at incidence p (the pavilion angle: the facet is tilted p from the girdle plane, so its
// normal is tilted p from the -y axis). Diamond's critical angle is θc = asin(1/2.417) = 24.4°,
// so for any usual p it is totally reflected.
//
// The second incidence, in the meridian plane with r outward and y up: the first main's
// outward normal is n1 = (sin p, -cos p), the ray d = (0, -1). Reflecting,
// d' = d - 2 (d·n1) n1 = (-sin 2p, cos 2p). The opposite main has n2 = (-sin p, -cos p), so
// cos θ2 = d'·n2 = sin 2p sin p - cos 2p cos p = -cos 3p = cos(180° - 3p): θ2 = 180° - 3p.
// The light is totally reflected again, and returns up through the crown, when
// 180° - 3p > θc, i.e. p < (180° - θc)/3 = 51.9°; above that it leaks through the pavilion.
// (Measured from the stone's axis, p' = 90° - p, the same condition reads p' > (90° + θc)/3.)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "geometry/polyhedron.hpp"
#include "trace/tracer.hpp"
#include "trace_cut_stones.hpp"

namespace gem {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kN = test::kDiamondIndex;

// Unpolarised Fresnel reflectance from index n1 into n2 at incidence theta (Born & Wolf
// §1.5.2, written out here so that the expectation does not use the engine's optics).
double fresnel_by_hand(double theta, double n1, double n2) {
    const double st = n1 / n2 * std::sin(theta);
    if (st >= 1.0) return 1.0;
    const double ct = std::sqrt(1.0 - st * st), ci = std::cos(theta);
    const double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
    const double rp = (n1 * ct - n2 * ci) / (n1 * ct + n2 * ci);
    return 0.5 * (rs * rs + rp * rp);
}

struct MeridianResult {
    RayList list;
    Stone stone;
};

MeridianResult trace_meridian(double pavilion_deg) {
    CutParams params = default_cut_params(CutShape::round_brilliant);
    params.pavilion_angle_deg = pavilion_deg;
    Result<Stone> built = make_cut(params, test::constant_index_material(kN));
    MeridianResult result;
    if (!built) {
        ADD_FAILURE() << built.error();
        return result;
    }
    result.stone = std::move(built).value();
    const Stone& stone = result.stone;

    // The pavilion main's azimuth, from its plane.
    const Facet* main = nullptr;
    for (const Facet& f : stone.facets) {
        if (f.name == "pavilion main") main = &f;
    }
    if (!main) {
        ADD_FAILURE() << "no pavilion main";
        return result;
    }
    const double tilt = std::acos(-main->plane.n.y) / kDeg;
    EXPECT_NEAR(tilt, pavilion_deg, 1e-9) << "the main is not at the pavilion angle";
    const double azimuth = std::atan2(main->plane.n.z, main->plane.n.x);
    const double r = 0.3 * params.width_mm / 2.0;
    const Ray ray{{r * std::cos(azimuth), 10.0, r * std::sin(azimuth)}, {0.0, -1.0, 0.0}};

    TraceSettings settings;
    settings.max_depth = 30;
    settings.min_weight = 1e-9;
    Tracer(stone).trace(ray, kN, settings, result.list);
    EXPECT_TRUE(result.list.hit);
    EXPECT_EQ(stone.facets[result.list.reflected.facet].kind, FacetKind::table);
    return result;
}

const TracedRay& strongest_exit(const RayList& list) {
    EXPECT_FALSE(list.exits.empty());
    return *std::max_element(
        list.exits.begin(), list.exits.end(),
        [](const TracedRay& a, const TracedRay& b) { return a.weight < b.weight; });
}

class TraceMeridian : public ::testing::TestWithParam<double> {};

TEST_P(TraceMeridian, ReturnsThroughTheCrownOrLeaksThroughThePavilion) {
    const double p = GetParam();
    const MeridianResult m = trace_meridian(p);
    const RayList& list = m.list;
    const double critical = std::asin(1.0 / kN) / kDeg;
    const bool returns = 180.0 - 3.0 * p > critical;
    ASSERT_EQ(returns, p < (180.0 - critical) / 3.0);

    // Total internal reflection at the first main: nothing leaves at bounce 0.
    for (const TracedRay& e : list.exits) EXPECT_NE(e.bounces, 0) << "p = " << p;

    const TracedRay& best = strongest_exit(list);
    const FacetKind kind = m.stone.facets[best.facet].kind;
    if (returns) {
        EXPECT_TRUE(kind == FacetKind::table || kind == FacetKind::crown)
            << "p = " << p << " left through " << m.stone.facets[best.facet].name;
        for (const TracedRay& e : list.exits) EXPECT_NE(e.bounces, 1) << "p = " << p;
        return;
    }
    // Leaks at the opposite main, at incidence 180° - 3p: the weight is the table's normal
    // incidence transmission times the main's transmission.
    EXPECT_EQ(kind, FacetKind::pavilion) << "p = " << p;
    EXPECT_EQ(m.stone.facets[best.facet].name, "pavilion main");
    EXPECT_EQ(best.bounces, 1);
    const double r0 = std::pow((kN - 1.0) / (kN + 1.0), 2.0);
    const double theta2 = (180.0 - 3.0 * p) * kDeg;
    EXPECT_NEAR(best.weight, (1.0 - r0) * (1.0 - fresnel_by_hand(theta2, kN, 1.0)), 1e-9);
    // Snell: the exit ray makes asin(n sin θ2) with the main's normal.
    const double out_angle =
        std::acos(glm::dot(best.direction, m.stone.facets[best.facet].plane.n));
    EXPECT_NEAR(out_angle, std::asin(kN * std::sin(theta2)), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(PavilionAngles, TraceMeridian,
                         ::testing::Values(38.0, 41.0, 44.0, 50.5, 53.0, 56.0),
                         [](const auto& param_info) {
                             // Appended, not "p" + …: GCC 12 at -O3 warns falsely on that.
                             std::string name = "p";
                             name += std::to_string(int(param_info.param * 10));
                             return name;
                         });

}  // namespace
}  // namespace gem
