// Failure mode 2: grazing views. The fixture stores views down to −10° elevation (a ring shows
// the crown), spaced 12°. Views in the girdle plane are still served by a stored view within
// the grid's covering radius; views below the band are lifted to its rim (ViewGrid::
// into_range), so the table shows a view at least (−10° − elevation) away: seen from below, the
// stone is drawn as seen from the side. The angle TableFrameStats reports is bounded by
// geometry computed here by brute force, and the image error is measured.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "failure_render.hpp"
#include "gpu_table_fixture.hpp"
#include "gpu_test_support.hpp"
#include "picture/image_error.hpp"

namespace gem {
namespace {

constexpr int kImage = 128;

using failure::angle_between;

glm::dvec3 direction(double elevation_deg, double azimuth_deg) {
    const double e = glm::radians(elevation_deg);
    const double a = glm::radians(azimuth_deg);
    return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

double nearest_stored_angle(const ViewGrid& grid, const glm::dvec3& d) {
    double best = 10.0;
    for (const glm::dvec3& s : grid.directions()) {
        for (const glm::dmat3& h : grid.group()) best = std::min(best, angle_between(h * s, d));
    }
    return best;
}

// The covering radius of the stored views over the band (elevation ≥ the minimum): the
// largest angle from a direction of the band to its nearest stored image, by brute force over
// a dense Fibonacci sample of the band plus its rim (where lifted directions land); `inner`
// over the part more than one spacing above the minimum, `rim` over the rest.
struct Covering {
    double inner = 0.0;
    double rim = 0.0;
    double whole() const { return std::max(inner, rim); }
};

Covering covering_radius(const ViewGrid& grid) {
    const double min_el = grid.spec().min_elevation_rad;
    const double spacing = grid.spec().spacing_rad;
    Covering c;
    constexpr std::uint32_t kSamples = 6000;
    for (std::uint32_t i = 0; i < kSamples; ++i) {
        const glm::dvec3 d = ViewGrid::sphere_point(i, kSamples);
        const double elevation = std::asin(d.y);
        if (elevation < min_el) continue;
        double& worst = elevation > min_el + spacing ? c.inner : c.rim;
        worst = std::max(worst, nearest_stored_angle(grid, d));
    }
    for (int a = 0; a < 720; ++a) {
        c.rim =
            std::max(c.rim, nearest_stored_angle(grid, direction(glm::degrees(min_el), a * 0.5)));
    }
    return c;
}

// Intersection over union of the stone masks (alpha > 0.5) of two images.
double coverage_iou(const Image& a, const Image& b) {
    double both = 0.0;
    double either = 0.0;
    for (std::size_t p = 0; p < a.pixels.size(); ++p) {
        const bool x = a.pixels[p].w > 0.5f;
        const bool y = b.pixels[p].w > 0.5f;
        both += (x && y) ? 1.0 : 0.0;
        either += (x || y) ? 1.0 : 0.0;
    }
    return either > 0.0 ? both / either : 1.0;
}

// `image` with alpha 1 where either image shows the stone, 0 elsewhere, so that compare_images'
// only_stone option measures the stone and not the background. The background is left out
// because at exactly 0° the camera looks along the studio's horizon, where its radiance
// steps from floor to wall: the CPU reference takes one value there and the GPU's filtered
// cube map the average, which alone puts ΔE ≈ 10 over the whole background.
Image stone_masked(const Image& image, const Image& a, const Image& b) {
    Image out = image;
    for (std::size_t p = 0; p < out.pixels.size(); ++p) {
        out.pixels[p].w = (a.pixels[p].w > 0.5f || b.pixels[p].w > 0.5f) ? 1.0f : 0.0f;
    }
    return out;
}

TEST(FailureGrazing, AngleIsBoundedByTheBandAndTheImageDegradesBelowIt) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto fx = gpu_test::round_brilliant_database();
    ASSERT_TRUE(fx.ok()) << fx.error();
    auto scene = failure::FailureScene::make(fx.value()->database);
    ASSERT_TRUE(scene.ok()) << scene.error();
    const Database& db = *fx.value()->database;
    const ViewGrid& grid = db.grid();
    const double min_el = glm::degrees(grid.spec().min_elevation_rad);
    const Covering covering = covering_radius(grid);
    const double rho = covering.whole();
    // Measured 9.4° inside the band and 11.6° along its rim, where the band's edge cuts the
    // Fibonacci lattice: a direction just above −10° can be almost a full spacing from a view.
    std::printf("band from %.0f°, spacing %.0f°, covering radius %.2f° inside, %.2f° at the rim\n",
                min_el, glm::degrees(grid.spec().spacing_rad), glm::degrees(covering.inner),
                glm::degrees(covering.rim));

    struct Row {
        double elevation;
        double angle_deg;
        ImageError error;  // on the stone
        double iou;
    };
    std::vector<Row> rows;
    constexpr double kAzimuth = 17.0;  // generic: on no mirror plane of the round brilliant
    for (const double elevation : {5.0, 2.0, 0.0, -10.0, -30.0, -60.0}) {
        const glm::dvec3 d = direction(elevation, kAzimuth);
        auto camera = gpu_test::table_aligned_camera(db, d, 0.0, 128, kImage);
        ASSERT_TRUE(camera.ok()) << camera.error();
        auto with_background = scene.value().table(camera.value(), false, true);
        auto stone_only = scene.value().table(camera.value(), false, false);
        ASSERT_TRUE(with_background.ok()) << with_background.error();
        ASSERT_TRUE(stone_only.ok()) << stone_only.error();
        const Image exact = scene.value().exact(camera.value());
        const Image& mask = stone_only.value().image;
        ErrorOptions on_stone;
        on_stone.only_stone = true;
        auto error = compare_images(stone_masked(with_background.value().image, mask, exact),
                                    stone_masked(exact, mask, exact), on_stone);
        ASSERT_TRUE(error.ok()) << error.error();
        const double angle = with_background.value().stats.angle_rad;
        rows.push_back({elevation, glm::degrees(angle), error.value(),
                        coverage_iou(stone_only.value().image, exact)});
        if (elevation >= min_el) {
            // In the band the shown view is the nearest stored image (brute force), hence
            // within the covering radius.
            EXPECT_NEAR(angle, nearest_stored_angle(grid, d), 1e-9) << elevation;
            EXPECT_LE(angle, rho + 1e-9) << elevation;
        } else {
            // Below it: every stored image has elevation ≥ the minimum (the folding group
            // keeps +y), so none is nearer than (minimum − elevation); the view shown is the
            // nearest to the rim point of the same azimuth, so by the triangle inequality it
            // is within (minimum − elevation) + covering radius.
            const double gap = glm::radians(min_el - elevation);
            EXPECT_GE(angle, gap - 1e-9) << elevation;
            EXPECT_LE(angle, gap + rho + 1e-9) << elevation;
        }
    }
    // The image: within the band the silhouette moves little over the covering radius (mask
    // IoU measured 0.95–0.98 against the exact image; bound 0.9); 50° below the band the table
    // draws the stone from the side instead of from below, so the outline itself is wrong
    // (IoU measured 0.54; bound 0.8) and most of the stone is visibly wrong.
    // Within the band a grazing view 4–8° from a stored one already has most of the stone
    // visibly wrong (the sparkle pattern moves fast near the girdle); below it, where the
    // outline is wrong too, stone is compared with background, and the mean ΔE00 is over
    // twice the worst in the band (measured 44.2 against 18.2).
    double worst_in_band = 0.0;
    for (const Row& r : rows) {
        if (r.elevation >= min_el) {
            EXPECT_GT(r.iou, 0.9) << r.elevation;
            worst_in_band = std::max(worst_in_band, r.error.delta_e_mean);
        }
    }
    EXPECT_LT(rows.back().iou, 0.8);
    EXPECT_GT(rows.back().error.delta_e_mean, 2.0 * worst_in_band);
    std::printf(
        "(errors on the stone only)\nelevation  angle shown  PSNR    ΔE mean  ΔE p99  visible  "
        "mask IoU\n");
    for (const Row& r : rows) {
        std::printf("%6.0f°    %6.1f°    %5.1f dB  %5.2f   %6.2f   %5.1f%%   %.3f\n", r.elevation,
                    r.angle_deg, r.error.psnr_db, r.error.delta_e_mean, r.error.delta_e_p99,
                    100.0 * r.error.share_visible, r.iou);
    }
}

}  // namespace
}  // namespace gem
