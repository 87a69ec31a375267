// The view grid: nearest lookups against brute force, folding by C8v, the canonical basis,
// and the image map checked by tracing a symmetric toy stone both ways.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "gemdb/view_grid.hpp"
#include "tables_test_support.hpp"

namespace gem {
namespace {

using tables_test::cnv;
using tables_test::random_unit;

ViewGrid make_grid(double spacing, double min_elevation, const std::vector<glm::dmat3>& group) {
    auto grid = ViewGrid::build({spacing, min_elevation}, group);
    EXPECT_TRUE(grid.ok()) << (grid.ok() ? "" : grid.error());
    return std::move(grid.value());
}

glm::dvec3 random_in_range(std::mt19937_64& rng, double min_elevation) {
    for (;;) {
        const glm::dvec3 v = random_unit(rng);
        if (std::asin(v.y) >= min_elevation) return v;
    }
}

// All distinct images h·s of the stored views with their distance to v, nearest first.
std::vector<std::pair<double, std::uint32_t>> brute_force(const ViewGrid& grid,
                                                          const glm::dvec3& v) {
    std::vector<std::pair<double, std::uint32_t>> all;
    for (std::uint32_t s = 0; s < grid.size(); ++s) {
        std::vector<glm::dvec3> images;
        for (const glm::dmat3& h : grid.group()) {
            const glm::dvec3 p = h * grid.direction(s);
            if (std::any_of(images.begin(), images.end(),
                            [&](const glm::dvec3& q) { return glm::length(q - p) < 1e-12; })) {
                continue;
            }
            images.push_back(p);
            all.push_back({glm::length(p - v), s});
        }
    }
    std::sort(all.begin(), all.end());
    return all;
}

TEST(TablesViewGrid, NearestEqualsBruteForce) {
    struct Case {
        double spacing, min_elevation;
        std::vector<glm::dmat3> group;
    };
    const std::vector<Case> cases = {{0.12, -std::numbers::pi / 2, cnv(8)},
                                     {0.1, 0.0, cnv(8)},
                                     {0.2, -std::numbers::pi / 2, {glm::dmat3(1.0)}},
                                     {0.05, 0.3, cnv(3)}};
    std::mt19937_64 rng(11);
    for (const Case& c : cases) {
        const ViewGrid grid = make_grid(c.spacing, c.min_elevation, c.group);
        for (int i = 0; i < 300; ++i) {
            const glm::dvec3 v = random_in_range(rng, c.min_elevation);
            const auto expected = brute_force(grid, v);
            std::array<ViewMatch, 6> got{};
            ASSERT_EQ(grid.nearest_k(v, got), got.size());
            for (std::size_t k = 0; k < got.size(); ++k) {
                // The angle the grid reports is the chord distance the scan found.
                EXPECT_NEAR(2.0 * std::sin(got[k].angle / 2.0), expected[k].first, 1e-12)
                    << "spacing " << c.spacing << " rank " << k;
            }
            EXPECT_EQ(got[0].view, expected[0].second);
            EXPECT_EQ(grid.nearest(v).view, expected[0].second);
        }
    }
}

TEST(TablesViewGrid, FoldsOneSixteenthForC8v) {
    const ViewGrid full = make_grid(0.05, -std::numbers::pi / 2, cnv(8));
    const double n = full.sphere_count();
    EXPECT_EQ(n, std::ceil(4.0 * std::numbers::pi / (0.05 * 0.05)));
    EXPECT_EQ(full.group().size(), 16u);
    // One fundamental domain holds 1/16 of the sphere; views near its mirror walls, kept
    // 0.9 spacing from their own mirror images, add a little.
    EXPECT_GE(full.size(), 0.95 * n / 16.0);
    EXPECT_LE(full.size(), 1.3 * n / 16.0);
    // Above the girdle only: half of that.
    const ViewGrid crown = make_grid(0.05, 0.0, cnv(8));
    EXPECT_GE(crown.size(), 0.95 * n / 32.0);
    EXPECT_LE(crown.size(), 1.3 * n / 32.0);
    for (const glm::dvec3& d : crown.directions()) EXPECT_GE(d.y, 0.0);
    // Without symmetry nothing folds: about one view per lattice point.
    const ViewGrid plain = make_grid(0.1, -std::numbers::pi / 2, {glm::dmat3(1.0)});
    EXPECT_GE(plain.size(), 0.95 * plain.sphere_count());
}

TEST(TablesViewGrid, CoveringRadiusBelowSpacing) {
    // Every direction is within one spacing of a stored view's image. (A hexagonal lattice
    // with area A per point would reach √(2A / (3√3)) ≈ 0.62 √A; folding costs some of that.)
    const double spacing = 0.08;
    for (const auto& group : {cnv(8), std::vector<glm::dmat3>{glm::dmat3(1.0)}}) {
        const ViewGrid grid = make_grid(spacing, -std::numbers::pi / 2, group);
        std::mt19937_64 rng(2);
        double worst = 0.0;
        for (int i = 0; i < 20000; ++i)
            worst = std::max(worst, grid.nearest(random_unit(rng)).angle);
        EXPECT_LE(worst, spacing) << "group order " << group.size();
        EXPECT_GE(worst, 0.4 * spacing);
    }
}

TEST(TablesViewGrid, LookupIsInvariantUnderEveryGroupElement) {
    const ViewGrid grid = make_grid(0.07, 0.1, cnv(8));
    std::mt19937_64 rng(4);
    for (int i = 0; i < 400; ++i) {
        const glm::dvec3 v = random_in_range(rng, 0.1);
        const ViewMatch base = grid.nearest(v);
        const glm::dvec3 s = grid.direction(base.view);
        for (const glm::dmat3& g : grid.group()) {
            const glm::dvec3 w = g * v;
            const ViewMatch m = grid.nearest(w);
            EXPECT_EQ(m.view, base.view);
            EXPECT_NEAR(m.angle, base.angle, 1e-12);
            // The returned element folds the asked direction onto the stored view.
            EXPECT_NEAR(glm::length(grid.group()[m.symmetry] * w - s),
                        glm::length(grid.group()[base.symmetry] * v - s), 1e-12);
        }
    }
    // Below the range, directions are lifted onto the rim and still fold consistently.
    const glm::dvec3 below = glm::normalize(glm::dvec3(0.3, -0.8, 0.5));
    const ViewMatch rim = grid.nearest(below);
    EXPECT_LT(std::asin(grid.direction(rim.view).y), 0.1 + 0.07);
    for (const glm::dmat3& g : grid.group()) EXPECT_EQ(grid.nearest(g * below).view, rim.view);
}

TEST(TablesViewGrid, CanonicalBasisIsRightHandedWithUpTowardY) {
    std::mt19937_64 rng(8);
    for (int i = 0; i < 1000; ++i) {
        const glm::dvec3 v = random_unit(rng);
        const CameraBasis b = canonical_basis(v);
        EXPECT_NEAR(glm::length(b.right), 1.0, 1e-12);
        EXPECT_NEAR(glm::length(b.up), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(b.right, b.up), 0.0, 1e-12);
        EXPECT_NEAR(glm::length(glm::cross(b.right, b.up) - v), 0.0, 1e-12);
        if (std::abs(v.y) < kPoleCos) {
            EXPECT_GE(b.up.y, 0.0);
        }
    }
    // Seen from +z, up is +y and right is +x; straight above, up is -z and right +x.
    const CameraBasis front = canonical_basis({0, 0, 1});
    EXPECT_NEAR(glm::length(front.up - glm::dvec3(0, 1, 0)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(front.right - glm::dvec3(1, 0, 0)), 0.0, 1e-15);
    const CameraBasis top = canonical_basis({0, 1, 0});
    EXPECT_NEAR(glm::length(top.up - glm::dvec3(0, 0, -1)), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(top.right - glm::dvec3(1, 0, 0)), 0.0, 1e-15);
}

// A toy stand-in for the tracer, independent of the code under test: a convex stone with
// C8v symmetry (table, 8 crown and 8 pavilion planes); a ray's "list" is its entry point,
// mirror reflection and the straight continuation to the far side, with facet numbers.
struct ToyHit {
    glm::dvec3 entry, reflected, exit;
    int entry_facet = -1, exit_facet = -1;
};

std::vector<glm::dvec4> toy_planes() {
    std::vector<glm::dvec4> planes{{0.0, 1.0, 0.0, 0.6}};
    const double crown = 0.6, pavilion = 0.86;  // tilts from the table axis, radians
    for (int k = 0; k < 8; ++k) {
        const double a = k * std::numbers::pi / 4.0;
        planes.push_back(
            {std::sin(a) * std::sin(crown), std::cos(crown), std::cos(a) * std::sin(crown), 1.0});
    }
    for (int k = 0; k < 8; ++k) {
        const double a = (k + 0.5) * std::numbers::pi / 4.0;
        planes.push_back({std::sin(a) * std::sin(pavilion), -std::cos(pavilion),
                          std::cos(a) * std::sin(pavilion), 1.2});
    }
    return planes;
}

std::optional<ToyHit> toy_trace(const std::vector<glm::dvec4>& planes, const glm::dvec3& o,
                                const glm::dvec3& d) {
    double t_in = -1e30, t_out = 1e30;
    ToyHit hit;
    for (std::size_t i = 0; i < planes.size(); ++i) {
        const glm::dvec3 n(planes[i]);
        const double nd = glm::dot(n, d);
        const double t = (planes[i].w - glm::dot(n, o)) / nd;
        if (nd < 0.0 && t > t_in) {
            t_in = t;
            hit.entry_facet = static_cast<int>(i);
        } else if (nd > 0.0 && t < t_out) {
            t_out = t;
            hit.exit_facet = static_cast<int>(i);
        }
    }
    if (!(t_in < t_out)) return std::nullopt;
    const glm::dvec3 n(planes[static_cast<std::size_t>(hit.entry_facet)]);
    hit.entry = o + t_in * d;
    hit.reflected = d - 2.0 * glm::dot(d, n) * n;
    hit.exit = o + t_out * d;
    return hit;
}

TEST(TablesViewGrid, ImageMapReconstructsTheAskedView) {
    const auto group = cnv(8);
    const ViewGrid grid = make_grid(0.15, 0.05, group);
    const auto planes = toy_planes();
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
    int compared = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const std::uint32_t s = static_cast<std::uint32_t>(rng() % grid.size());
        const glm::dmat3& h = grid.group()[rng() % grid.group().size()];
        const glm::dvec3 v = h * grid.direction(s);  // exactly on the orbit of a stored view
        // The asked camera has an arbitrary roll about v.
        const CameraBasis c = canonical_basis(v);
        const double roll = angle(rng);
        const glm::dvec3 right = std::cos(roll) * c.right + std::sin(roll) * c.up;
        const glm::dvec3 up = -std::sin(roll) * c.right + std::cos(roll) * c.up;
        const ViewMatch m = grid.nearest(v);
        EXPECT_NEAR(glm::length(grid.direction(m.view) - grid.direction(s)), 0.0, 1e-12);
        EXPECT_LT(m.angle, 1e-7);
        const glm::dmat2 map = grid.image_map(m, v, right, up);
        EXPECT_NEAR(std::abs(glm::determinant(map)), 1.0, 1e-9);
        const glm::dmat3 g_inv = glm::transpose(grid.group()[m.symmetry]);
        const CameraBasis stored = grid.basis(m.view);
        for (double x = -1.3; x <= 1.3; x += 0.37) {
            for (double y = -1.3; y <= 1.3; y += 0.41) {
                const auto direct = toy_trace(planes, x * right + y * up + 5.0 * v, -v);
                const glm::dvec2 q = map * glm::dvec2(x, y);
                const auto folded = toy_trace(
                    planes, q.x * stored.right + q.y * stored.up + 5.0 * stored.view, -stored.view);
                ASSERT_EQ(direct.has_value(), folded.has_value()) << x << " " << y;
                if (!direct) continue;
                ++compared;
                EXPECT_NEAR(glm::length(g_inv * folded->entry - direct->entry), 0.0, 1e-9);
                EXPECT_NEAR(glm::length(g_inv * folded->reflected - direct->reflected), 0.0, 1e-9);
                EXPECT_NEAR(glm::length(g_inv * folded->exit - direct->exit), 0.0, 1e-9);
                // Facet numbers permute: the facet hit in the stored view, carried back by
                // g⁻¹, is the one hit directly.
                const glm::dvec3 n_folded(planes[static_cast<std::size_t>(folded->entry_facet)]);
                const glm::dvec3 n_direct(planes[static_cast<std::size_t>(direct->entry_facet)]);
                EXPECT_NEAR(glm::length(g_inv * n_folded - n_direct), 0.0, 1e-9);
            }
        }
    }
    EXPECT_GT(compared, 1000);
}

TEST(TablesViewGrid, BadSpecsAndGroupsAreErrors) {
    auto tiny = ViewGrid::build({0.0001, 0.0}, cnv(8));
    ASSERT_FALSE(tiny.ok());
    EXPECT_NE(tiny.error().find("spacing_rad"), std::string::npos);
    auto up = ViewGrid::build({0.1, 2.0}, cnv(8));
    ASSERT_FALSE(up.ok());
    EXPECT_NE(up.error().find("min_elevation_rad"), std::string::npos);
    auto open = ViewGrid::build({0.1, 0.0}, {glm::dmat3(1.0), tables_test::rotation_y(0.3)});
    ASSERT_FALSE(open.ok());
    EXPECT_NE(open.error().find("not a group"), std::string::npos);
    // Matrices of NaN compare as neither equal nor different; they must not pass as a group.
    const glm::dmat3 nan(std::numeric_limits<double>::quiet_NaN());
    auto broken = ViewGrid::build({0.1, 0.0}, {nan, nan});
    EXPECT_FALSE(broken.ok());
}

}  // namespace
}  // namespace gem
