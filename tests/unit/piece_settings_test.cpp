// The parametric settings hold their stones as a jeweller's would. Every check here is made
// independently of how the settings were built: contacts by sampling each claw tip's or bead's
// sphere densely and measuring depth against the stone's facet planes (the deepest point of a
// convex solid is the least of its planes' depths), stone overlaps by testing points sampled
// over one stone's surface against the other's planes, and the tip heights against the stone's
// own vertices.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "optics/material.hpp"
#include "piece/metal_mesh.hpp"
#include "piece/piece_check.hpp"
#include "piece/seat.hpp"
#include "piece/settings.hpp"
#include "piece/stone_shape.hpp"
#include "trace_cut_stones.hpp"

namespace gem {
namespace {

// How far a point (stone frame) lies inside a convex stone: the least depth below its planes;
// negative outside.
double depth_inside(const Stone& stone, const glm::dvec3& p) {
    double worst = -1e300;
    for (const Facet& f : stone.facets) worst = std::max(worst, f.plane.signed_distance(p));
    return -worst;
}

// Points spread evenly over the unit sphere (a Fibonacci lattice).
std::vector<glm::dvec3> sphere_points(int n) {
    std::vector<glm::dvec3> out;
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / n;
        const double r = std::sqrt(1.0 - y * y);
        out.emplace_back(r * std::cos(golden * i), y, r * std::sin(golden * i));
    }
    return out;
}

struct Contact {
    double overlap = 0.0;    // deepest sampled point of the ball inside the stone
    double contact_y = 0.0;  // that point's height in the stone's frame
};

Contact contact_of(const Piece& piece, const Hold& hold) {
    static const std::vector<glm::dvec3> unit = sphere_points(6000);
    const Stone& stone = piece.stone_of(hold.stone);
    const Placement& place = piece.stones[hold.stone].placement;
    Contact c{-1e300, 0.0};
    for (const glm::dvec3& u : unit) {
        const glm::dvec3 p = place.to_stone(hold.centre + hold.radius * u);
        const double d = depth_inside(stone, p);
        if (d > c.overlap) c = {d, p.y};
    }
    return c;
}

std::vector<glm::dvec3> surface_samples(const Stone& s) {
    std::vector<glm::dvec3> out = s.vertices;
    for (const MeshTriangle& t : s.triangles) {
        const glm::dvec3 a = s.vertices[t.v[0]], b = s.vertices[t.v[1]], c = s.vertices[t.v[2]];
        out.push_back((a + b + c) / 3.0);
        out.push_back(0.5 * (a + b));
        out.push_back(0.5 * (b + c));
        out.push_back(0.5 * (c + a));
    }
    return out;
}

Piece setting(SettingKind kind) {
    SettingParams p;
    p.kind = kind;
    std::optional<Stone> centre, small;
    if (kind != SettingKind::band) centre = test::round_diamond(6.5);
    if (kind == SettingKind::halo) small = test::round_diamond(1.3);
    if (kind == SettingKind::three_stone) small = test::round_diamond(4.0);
    if (kind == SettingKind::band) small = test::round_diamond(1.8);
    auto piece = make_setting(p, to_string(kind), centre, small);
    EXPECT_TRUE(piece) << (piece ? "" : piece.error());
    return std::move(piece).value();
}

class EverySetting : public ::testing::TestWithParam<SettingKind> {};

// The renderer culls a closed mesh's back faces (MetalMesh::closed); that is right only if
// every triangle's winding (counter-clockwise seen from outside) agrees with the outward
// normals given at its corners.
TEST_P(EverySetting, ItsMetalIsClosedAndWoundOutward) {
    const Piece piece = setting(GetParam());
    EXPECT_TRUE(piece.metal.closed);
    const MetalMesh& m = piece.metal;
    std::size_t against = 0, degenerate = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]),
            c(m.positions[m.indices[t + 2]]);
        const glm::dvec3 wound = glm::cross(b - a, c - a);
        if (glm::length(wound) < 1e-12) {
            ++degenerate;
            continue;
        }
        const glm::dvec3 given(m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] +
                               m.normals[m.indices[t + 2]]);
        if (glm::dot(wound, given) <= 0.0) ++against;
    }
    EXPECT_EQ(against, 0u) << "of " << m.indices.size() / 3 << " triangles";
    EXPECT_LT(degenerate, m.indices.size() / 300) << "of " << m.indices.size() / 3;
}

TEST_P(EverySetting, EachClawTipOrBeadBearsOnItsStonesCrownNoDeeperThanTheSeat) {
    const Piece piece = setting(GetParam());
    ASSERT_FALSE(piece.holds.empty());
    for (const Hold& hold : piece.holds) {
        const Contact c = contact_of(piece, hold);
        const StoneExtent e = stone_extent(piece.stone_of(hold.stone));
        const std::string who = piece.stones[hold.stone].role;
        // It touches (no gap) and is seated no deeper than a setter files; the sampling's
        // spacing (0.01 mm on a 0.5 mm ball) loses at most a few microns of the overlap.
        EXPECT_GT(c.overlap, 0.5 * kSeatMm) << who;
        EXPECT_LE(c.overlap, kSeatMm + 1e-6) << who;
        // ... on the crown, above the girdle.
        EXPECT_GE(c.contact_y, e.girdle_top - 1e-3) << who;
    }
}

TEST_P(EverySetting, EveryStoneIsHeldFromAtLeastThreeSidesOrByFourClaws) {
    const Piece piece = setting(GetParam());
    std::map<std::size_t, int> holds;
    for (const Hold& h : piece.holds) ++holds[h.stone];
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        EXPECT_GE(holds[i], 4) << piece.stones[i].role;
    }
}

TEST_P(EverySetting, NoMetalCutsIntoAStoneDeeperThanTheSeat) {
    const Piece piece = setting(GetParam());
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        const Stone& stone = piece.stone_of(i);
        double deepest = 0.0;
        for (const glm::vec3& v : piece.metal.positions) {
            deepest = std::max(
                deepest, depth_inside(stone, piece.stones[i].placement.to_stone(glm::dvec3(v))));
        }
        EXPECT_LE(deepest, kSeatMm + 1e-6) << piece.stones[i].role;
    }
}

// Rays from each stone's centre outward: any metal they meet inside the stone must lie within a
// seat of its surface, so no claw, wall or bead passes through a stone between its vertices. Möller
// and Trumbore's ray-triangle test, written here apart from the engine's.
double ray_hits_triangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a,
                         const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, q = glm::cross(d, e2);
    const double det = glm::dot(e1, q);
    if (std::abs(det) < 1e-14) return -1.0;
    const glm::dvec3 t = o - a;
    const double u = glm::dot(t, q) / det;
    if (u < 0.0 || u > 1.0) return -1.0;
    const glm::dvec3 r = glm::cross(t, e1);
    const double v = glm::dot(d, r) / det;
    if (v < 0.0 || u + v > 1.0) return -1.0;
    return glm::dot(e2, r) / det;
}

TEST_P(EverySetting, RaysFromEachStonesCentreLeaveTheStoneBeforeTheyMeetMetal) {
    const Piece piece = setting(GetParam());
    const std::vector<glm::dvec3> directions = sphere_points(400);
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        const Stone& stone = piece.stone_of(i);
        const Placement& place = piece.stones[i].placement;
        double radius = 0.0;
        for (const glm::dvec3& v : stone.vertices) radius = std::max(radius, glm::length(v));
        // The metal's triangles near the stone, in its frame.
        std::vector<std::array<glm::dvec3, 3>> near;
        for (std::size_t t = 0; t < piece.metal.indices.size(); t += 3) {
            std::array<glm::dvec3, 3> tri;
            bool close = false;
            for (int k = 0; k < 3; ++k) {
                tri[k] =
                    place.to_stone(glm::dvec3(piece.metal.positions[piece.metal.indices[t + k]]));
                close = close || glm::length(tri[k]) < radius + 1.0;
            }
            if (close) near.push_back(tri);
        }
        int cut = 0;
        for (const glm::dvec3& d : directions) {
            for (const auto& tri : near) {
                const double t = ray_hits_triangle(glm::dvec3(0.0), d, tri[0], tri[1], tri[2]);
                // Metal met inside the stone, deeper below its surface than a seat.
                if (t > 0.0 && depth_inside(stone, t * d) > kSeatMm + 1e-6) ++cut;
            }
        }
        EXPECT_EQ(cut, 0) << piece.stones[i].role;
        if (GetParam() == SettingKind::band && i >= 3) break;  // the band's stones are alike
    }
}

TEST_P(EverySetting, NoTwoStonesIntersect) {
    const Piece piece = setting(GetParam());
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        const std::vector<glm::dvec3> samples = surface_samples(piece.stone_of(i));
        for (std::size_t j = 0; j < piece.stones.size(); ++j) {
            if (i == j) continue;
            double deepest = -1e300;
            for (const glm::dvec3& s : samples) {
                const glm::dvec3 p =
                    piece.stones[j].placement.to_stone(piece.stones[i].placement.to_piece(s));
                deepest = std::max(deepest, depth_inside(piece.stone_of(j), p));
            }
            EXPECT_LT(deepest, 0.0) << piece.stones[i].role << " in " << piece.stones[j].role;
        }
    }
}

TEST_P(EverySetting, PassesThePieceCheck) {
    const Piece piece = setting(GetParam());
    auto ok = check_piece(piece);
    EXPECT_TRUE(ok) << (ok ? "" : ok.error());
}

INSTANTIATE_TEST_SUITE_P(Settings, EverySetting,
                         ::testing::Values(SettingKind::solitaire, SettingKind::halo,
                                           SettingKind::three_stone, SettingKind::band),
                         [](const auto& param_info) {
                             std::string s = to_string(param_info.param);
                             std::replace(s.begin(), s.end(), '-', '_');
                             return s;
                         });

// A circle's chords, measured as points: the middle of the chord between two neighbouring
// vertices lies within the tolerance of the circle, and with one multiple fewer it would not.
TEST(Settings, WallsAreCutIntoTheFewestSegmentsWithinTheChordTolerance) {
    auto chord_gap = [](double r, int n) {
        const double step = 2.0 * std::numbers::pi / n;
        const glm::dvec2 a(r, 0.0), b(r * std::cos(step), r * std::sin(step));
        return r - glm::length(0.5 * (a + b));
    };
    for (const double r : {1.0, 4.8, 11.5, 30.0}) {
        for (const int multiple : {1, 22, 36}) {
            const int n = circle_segments(r, multiple);
            EXPECT_EQ(n % multiple, 0) << r << " " << multiple;
            EXPECT_LE(chord_gap(r, n), kChordToleranceMm) << r << " " << multiple;
            if (n > multiple) {
                EXPECT_GT(chord_gap(r, n - multiple), kChordToleranceMm) << r << " " << multiple;
            }
        }
    }
}

TEST(Settings, ClawTipsStandAtGiasNinetyToHundredPercentOfTheCrownHeight) {
    for (const SettingKind kind :
         {SettingKind::solitaire, SettingKind::halo, SettingKind::three_stone}) {
        const Piece piece = setting(kind);
        for (const Hold& h : piece.holds) {
            const PieceStone& ps = piece.stones[h.stone];
            if (ps.role.rfind("halo", 0) == 0) continue;  // beads, not claws
            // Girdle top and table height from the stone's own vertices.
            const Stone& stone = piece.stone_of(h.stone);
            double r = 0.0, table = -1e9, top = -1e9;
            for (const glm::dvec3& v : stone.vertices) {
                r = std::max(r, std::hypot(v.x, v.z));
                table = std::max(table, v.y);
            }
            for (const glm::dvec3& v : stone.vertices) {
                if (std::hypot(v.x, v.z) > 0.97 * r) top = std::max(top, v.y);
            }
            const double tip_top = ps.placement.to_stone(h.centre).y + h.radius;
            const double share = (tip_top - top) / (table - top);
            EXPECT_GE(share, 0.90) << to_string(kind) << " " << ps.role;
            EXPECT_LE(share, 1.00) << to_string(kind) << " " << ps.role;
        }
    }
}

TEST(Settings, AHaloHasTwentyOrMoreStonesAndABandThirtyOrMore) {
    EXPECT_GE(setting(SettingKind::halo).stones.size(), 21u);
    EXPECT_GE(setting(SettingKind::band).stones.size(), 30u);
    EXPECT_EQ(setting(SettingKind::three_stone).stones.size(), 3u);
    // Identical stones share one kind.
    EXPECT_EQ(setting(SettingKind::halo).kinds.size(), 2u);
    EXPECT_EQ(setting(SettingKind::band).kinds.size(), 1u);
}

TEST(Settings, AParameterOutOfRangeIsNamed) {
    SettingParams p;
    p.claws.width_mm = 5.0;
    auto bad = make_setting(p, "x", test::round_diamond(6.5), std::nullopt);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().rfind("claw_width_mm:", 0), 0u) << bad.error();
    p = SettingParams{};
    p.kind = SettingKind::band;
    p.row.count = 80;
    bad = make_setting(p, "x", std::nullopt, test::round_diamond(1.8));
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().rfind("count:", 0), 0u) << bad.error();
    p = SettingParams{};
    p.shank.finger_diameter_mm = 3.0;
    bad = make_setting(p, "x", test::round_diamond(6.5), std::nullopt);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().rfind("finger_diameter_mm:", 0), 0u) << bad.error();
}

// Two 2 mm round brilliants side by side: their girdles (radius 1 mm, faceted) overlap when
// the centres are closer than 2 mm less the girdle facets' sag, and not when farther than 2 mm.
TEST(Settings, StonesIntersectOnlyWhenTheyShareVolume) {
    const Stone s = test::round_diamond(2.0);
    const Placement a{};
    EXPECT_TRUE(stones_intersect(s, a, s, {glm::dmat3(1.0), {1.9, 0.0, 0.0}}));
    EXPECT_FALSE(stones_intersect(s, a, s, {glm::dmat3(1.0), {2.01, 0.0, 0.0}}));
    // One stone inside another, surfaces apart: still shared volume.
    EXPECT_TRUE(stones_intersect(test::round_diamond(6.0), a, test::round_diamond(0.5), a));
}

TEST(Settings, APieceWhoseStoneIsLiftedOffItsClawsFloats) {
    Piece piece = setting(SettingKind::solitaire);
    piece.stones[0].placement.position.y += 3.0;  // over its claw tips, touching nothing
    auto ok = check_piece(piece);
    ASSERT_FALSE(ok);
    EXPECT_NE(ok.error().find("stone 1 ('centre')"), std::string::npos) << ok.error();
    piece.stones[0].placement.position.y -= 3.5;  // pushed 0.5 mm down into its claws
    ok = check_piece(piece);
    ASSERT_FALSE(ok);
    EXPECT_NE(ok.error().find("cuts"), std::string::npos) << ok.error();
}

}  // namespace
}  // namespace gem
