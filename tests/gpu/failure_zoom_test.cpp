// Failure mode 4: zoom outside the stored levels. The fixture stores levels of 64 and 128
// pixels per side of the table camera's field. A stone a few pixels across is served by the
// smallest level (must not crash, and must cover the right pixels); a stone magnified far
// beyond the largest level is served by it upsampled: table.frag fetches the nearest stored
// pixel (texelFetch), so the picture is made of flat blocks one stored pixel wide. The level
// choice is checked against the pixel footprint computed by hand.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "failure_render.hpp"
#include "gpu_table_fixture.hpp"
#include "gpu_test_support.hpp"
#include "picture/image_error.hpp"

namespace gem {
namespace {

constexpr int kImage = 128;

class FailureZoom : public ::testing::Test {
  protected:
    void SetUp() override {
        auto ctx = gpu_test::context();
        ASSERT_TRUE(ctx.ok()) << ctx.error();
        auto fx = gpu_test::round_brilliant_database();
        ASSERT_TRUE(fx.ok()) << fx.error();
        database_ = fx.value()->database;
        auto scene = failure::FailureScene::make(database_);
        ASSERT_TRUE(scene.ok()) << scene.error();
        scene_ = std::make_unique<failure::FailureScene>(std::move(scene).value());
        radius_ = bounding_radius(scene_->stone().vertices);
        field_ = database_->camera().field_mm;
    }
    // Face-up: a stored view (the pole) whose camera basis is the stored one, so the image
    // map is the identity and stored pixels are axis-aligned squares on screen.
    Camera face_up(double zoom) const {
        auto camera = scene_->camera({0.0, 1.0, 0.0}, zoom, kImage);
        EXPECT_TRUE(camera.ok()) << camera.error();
        return camera.value();
    }
    // Stored-view pixels across the screen at level side s is s / (screen pixels per field);
    // the field spans field / pixel screen pixels, and Camera::make sizes a pixel as
    // 2R / (zoom · image side).
    double pixels_across(double zoom) const { return field_ * zoom * kImage / (2.0 * radius_); }

    std::shared_ptr<const Database> database_;
    std::unique_ptr<failure::FailureScene> scene_;
    double radius_ = 0.0;
    double field_ = 0.0;
};

// The hand rule: the smallest stored side (64, 128) at least as large as the footprint, or
// the largest when none is; the boundary lies at zoom = 64 · 2R / (field · 128).
TEST_F(FailureZoom, LevelChoiceMatchesTheHandComputedFootprint) {
    auto method = gpu::TableMethod::make(database_);
    ASSERT_TRUE(method.ok()) << method.error();
    ASSERT_EQ(database_->params().levels, (std::vector<std::uint32_t>{64, 128}));
    const double boundary = 64.0 * 2.0 * radius_ / (field_ * kImage);
    struct Case {
        double zoom;
        std::uint32_t level;
    };
    for (const Case c : {Case{0.05, 0}, Case{boundary * 0.99, 0}, Case{boundary * 1.01, 1},
                         Case{1.0, 1}, Case{8.0, 1}}) {
        const double across = pixels_across(c.zoom);
        EXPECT_EQ(method.value().level_for(across), c.level) << "zoom " << c.zoom;
        auto r = scene_->table(face_up(c.zoom), false, false);
        ASSERT_TRUE(r.ok()) << r.error();
        EXPECT_TRUE(r.value().stats.drawn);
        EXPECT_EQ(r.value().stats.level, c.level) << "zoom " << c.zoom;
        std::printf("zoom %.3f: footprint %.1f px → level %u\n", c.zoom, across,
                    r.value().stats.level);
    }
}

// A stone about 6 px across: drawn from the 64-pixel level, which is ten times finer than the
// screen, so the stored pixel fetched for a screen pixel lies within 0.05 screen pixels of
// its centre. Coverage can then differ from the exact image only where the silhouette passes
// that close to a pixel centre: with a perimeter of about 20 pixels, at most a couple.
TEST_F(FailureZoom, TinyStoneIsCoveredWhereTheExactImageIs) {
    const Camera camera = face_up(0.05);
    auto r = scene_->table(camera, false, false);
    ASSERT_TRUE(r.ok()) << r.error();
    const Image exact = scene_->exact(camera);
    int table_px = 0, exact_px = 0, mismatched = 0;
    for (std::size_t p = 0; p < exact.pixels.size(); ++p) {
        const bool t = r.value().image.pixels[p].w > 0.5f;
        const bool e = exact.pixels[p].w > 0.5f;
        table_px += t ? 1 : 0;
        exact_px += e ? 1 : 0;
        mismatched += t != e ? 1 : 0;
    }
    // Hand check of the exact mask: face-up the outline is the girdle, a near-circle of the
    // stone's largest horizontal radius; its area in screen pixels is π r² / pixel².
    double girdle = 0.0;
    for (const glm::dvec3& v : scene_->stone().vertices) {
        girdle = std::max(girdle, std::hypot(v.x, v.z));
    }
    const double disc = 3.14159265358979 * std::pow(girdle / camera.pixel_size(), 2.0);
    std::printf("tiny stone: table %d px, exact %d px, disc π r² = %.1f px, mismatched %d\n",
                table_px, exact_px, disc, mismatched);
    EXPECT_NEAR(exact_px, disc, 0.25 * disc);
    EXPECT_LE(mismatched, 2);
    EXPECT_GT(table_px, 0);
}

// Magnified 8× at the largest level (128): one stored pixel spans B = footprint / 128 ≈ 8.4
// screen pixels, so the table image is flat blocks. Defining property: two neighbouring
// screen pixels can differ only where they fetch different stored pixels, i.e. across a
// stored-pixel boundary computed here by hand.
TEST_F(FailureZoom, MagnifiedBeyondTheLargestLevelIsBlocky) {
    constexpr double kZoom = 8.0;
    const Camera camera = face_up(kZoom);
    auto stone_only = scene_->table(camera, false, false);
    auto shown = scene_->table(camera, false, true);
    ASSERT_TRUE(stone_only.ok() && shown.ok());
    const Image exact = scene_->exact(camera);
    ASSERT_EQ(stone_only.value().stats.level, 1u);
    const int side = 128;
    const double block = pixels_across(kZoom) / side;
    // Stored column (row) under the centre of screen column x (row y), as table.frag finds it.
    auto cell = [&](double screen) {
        const double q = (screen + 0.5 - 0.5 * kImage) * camera.pixel_size();
        return (q / field_ + 0.5) * side;
    };
    const std::vector<std::uint8_t> t8 = to_srgb8(shown.value().image, 3);
    const std::vector<std::uint8_t> e8 = to_srgb8(exact, 3);
    auto differs = [](const std::vector<std::uint8_t>& b, std::size_t p, std::size_t q) {
        return b[3 * p] != b[3 * q] || b[3 * p + 1] != b[3 * q + 1] || b[3 * p + 2] != b[3 * q + 2];
    };
    int pairs = 0, table_changes = 0, exact_changes = 0, off_boundary = 0;
    for (int y = 0; y < kImage; ++y) {
        for (int x = 0; x + 1 < kImage; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * kImage + x;
            if (stone_only.value().image.pixels[p].w < 0.5f ||
                stone_only.value().image.pixels[p + 1].w < 0.5f) {
                continue;
            }
            ++pairs;
            const bool change = differs(t8, p, p + 1);
            table_changes += change ? 1 : 0;
            exact_changes += differs(e8, p, p + 1) ? 1 : 0;
            // Same stored column, clear of a boundary by more than float rounding.
            const double c0 = cell(x);
            const double c1 = cell(x + 1);
            const bool same = std::floor(c0) == std::floor(c1) && c0 - std::floor(c0) > 1e-3 &&
                              std::ceil(c1) - c1 > 1e-3;
            if (change && same) ++off_boundary;
        }
    }
    auto error = compare_images(shown.value().image, exact);
    ASSERT_TRUE(error.ok()) << error.error();
    std::printf(
        "magnified ×%.0f: block %.2f px; horizontal changes: table %.1f%%, exact %.1f%% of "
        "%d pairs, off a block boundary %d; vs exact %.1f dB, ΔE mean %.2f, visible "
        "%.1f%%\n",
        kZoom, block, 100.0 * table_changes / pairs, 100.0 * exact_changes / pairs, pairs,
        off_boundary, error.value().psnr_db, error.value().delta_e_mean,
        100.0 * error.value().share_visible);
    ASSERT_GT(pairs, 1000);
    EXPECT_EQ(off_boundary, 0);
    // Changes can only happen at one pair in B, so at most 1 / B of the pairs.
    EXPECT_LE(table_changes, pairs / block + kImage);
    // The cost, measured: 17.2 dB and ΔE mean 3.3 against the exact image (53 dB at a stored
    // view with matched pixels, gpu_table_method_test.cpp); edges sit up to half a block
    // (4 px) from where they should, so the error is bounded below only loosely.
    EXPECT_GT(error.value().psnr_db, 12.0);
}

}  // namespace
}  // namespace gem
