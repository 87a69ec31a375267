// Folding checked with the real tracer on a round brilliant: a view asked anywhere on the
// orbit of a stored view, with any roll, equals g⁻¹ applied to the stored view's ray-lists at
// the pixel the image map moves it to.

#include <gtest/gtest.h>

#include <random>

#include "gemdb/database_types.hpp"
#include "gemdb/view_grid.hpp"
#include "geometry/cuts.hpp"
#include "trace/tracer.hpp"

namespace gem {
namespace {

bool same_ray(const TracedRay& a, const TracedRay& b, const glm::dmat3& g_inv) {
    return glm::length(g_inv * b.origin - a.origin) < 1e-6 &&
           glm::length(g_inv * b.direction - a.direction) < 1e-6 &&
           std::abs(a.weight - b.weight) < 1e-9 && a.bounces == b.bounces;
}

TEST(TablesFoldBrilliant, StoredViewReproducesEveryViewOnItsOrbit) {
    Material diamond;
    diamond.dispersion.coef = {2.417};
    auto cut = make_cut(default_cut_params(CutShape::round_brilliant), diamond);
    ASSERT_TRUE(cut.ok()) << cut.error();
    const Stone& stone = cut.value();
    ASSERT_EQ(stone.symmetry.size(), 16u) << "a round brilliant is C8v";
    auto built = ViewGrid::build({0.2, 0.05}, stone.symmetry);
    ASSERT_TRUE(built.ok()) << built.error();
    const ViewGrid& grid = built.value();
    const Tracer tracer(stone);
    const TraceSettings settings;
    const CameraModel camera{CameraModel::Kind::orthographic, 0.0, 8.0};
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> turn(0.0, 6.283185307179586);
    int compared = 0, differing = 0;
    RayList direct, folded;
    for (int trial = 0; trial < 12; ++trial) {
        const auto s = static_cast<std::uint32_t>(rng() % grid.size());
        const glm::dvec3 v = grid.group()[rng() % grid.group().size()] * grid.direction(s);
        const CameraBasis c = canonical_basis(v);
        const double roll = turn(rng);
        CameraBasis asked = c;
        asked.right = std::cos(roll) * c.right + std::sin(roll) * c.up;
        asked.up = -std::sin(roll) * c.right + std::cos(roll) * c.up;
        const ViewMatch m = grid.nearest(v);
        const glm::dmat2 map = grid.image_map(m, v, asked.right, asked.up);
        const glm::dmat3 g_inv = glm::transpose(grid.group()[m.symmetry]);
        for (std::uint32_t row = 0; row < 24; ++row) {
            for (std::uint32_t col = 0; col < 24; ++col) {
                const glm::dvec2 p = pixel_centre(col, row, 24, camera.field_mm);
                tracer.trace(camera_ray(camera, asked, p), 2.417, settings, direct);
                tracer.trace(camera_ray(camera, grid.basis(m.view), map * p), 2.417, settings,
                             folded);
                ASSERT_EQ(direct.hit, folded.hit);
                if (!direct.hit) continue;
                ++compared;
                // A ray grazing an edge or a critical angle may branch differently after
                // rounding; such pixels are counted, not failed.
                bool same = same_ray(direct.reflected, folded.reflected, g_inv) &&
                            direct.exits.size() == folded.exits.size();
                for (std::size_t e = 0; same && e < direct.exits.size(); ++e) {
                    same = same_ray(direct.exits[e], folded.exits[e], g_inv);
                }
                differing += same ? 0 : 1;
            }
        }
    }
    EXPECT_GT(compared, 2000);
    EXPECT_LE(differing, compared / 100) << differing << " of " << compared << " pixels differ";
}

}  // namespace
}  // namespace gem
