// The start view's framing (stage/framing.hpp), against outlines whose projections are worked
// out by hand: a camera looking straight down the y axis at zoom 1 sees x to the right.
#include <gtest/gtest.h>

#include "stage/framing.hpp"

namespace gem::kiosk {
namespace {

// Looking straight down (elevation 90, azimuth 0): right = +x, up = -z (camera.hpp).
constexpr ViewState kDown{.azimuth_deg = 0.0, .elevation_deg = 90.0, .roll_deg = 0.0, .zoom = 1.0};

// A square outline of half side `h` about (cx, 0, cz): on screen x = cx ± h, y = -cz ± h.
std::vector<glm::dvec3> square(double cx, double cz, double h) {
    return {{cx - h, 0, cz - h}, {cx + h, 0, cz - h}, {cx - h, 0, cz + h}, {cx + h, 0, cz + h}};
}

// Where a stone-frame point lands in ndc under the framed camera.
glm::dvec2 ndc_of(const glm::dvec3& p, const Framing& f, glm::ivec2 size, double radius) {
    const Camera c = Camera::make(framed_camera(kDown, f), radius, size.x, size.y).value();
    const glm::dvec2 mm(glm::dot(p, c.right()), glm::dot(p, c.up()));
    const glm::dvec2 half(0.5 * size.x * c.pixel_size(), 0.5 * size.y * c.pixel_size());
    return mm / half + c.shift();
}

TEST(Framing, TheWholeRingFitsTightlyAndTheStoneSitsAboveTheMiddle) {
    // Stone 6 mm wide at the origin; the ring spans y from -20 to +3 on screen (z = 20 down
    // to z = -3) and x ±9. Height needed: 23 mm / 0.92 = 25 mm, so the stone spans 6/25 of
    // it, more than a share of 0.2.
    const auto stone = square(0.0, 0.0, 3.0);
    const std::vector<glm::dvec3> ring = {{-9, 0, 20}, {9, 0, 20}, {0, 0, -3}};
    const glm::ivec2 size(1920, 1080);
    const Framing f = frame_ring(stone, ring, kDown, size, 25.0, 0.2);
    EXPECT_FALSE(f.ring_cut);
    EXPECT_NEAR(f.stone_share, 6.0 / 25.0, 1e-9);
    // The outline's middle (y = -8.5 mm) at the centre: the stone's centre 8.5 / 12.5 up.
    EXPECT_NEAR(f.shift.x, 0.0, 1e-9);
    EXPECT_NEAR(f.shift.y, 8.5 / 12.5, 1e-9);
    // Top and bottom sit at the margin exactly: ndc ±0.92.
    EXPECT_NEAR(ndc_of({0, 0, -3}, f, size, 25.0).y, 0.92, 1e-9);
    EXPECT_NEAR(ndc_of({0, 0, 20}, f, size, 25.0).y, -0.92, 1e-9);
}

TEST(Framing, WhenTheRingCannotFitTheStoneShareWinsAndTheStoneStaysWhole) {
    // The same stone in a ring twice as deep: the share 0.3 allows a picture 20 mm high.
    const auto stone = square(0.0, 0.0, 3.0);
    const std::vector<glm::dvec3> ring = {{-9, 0, 40}, {9, 0, 40}, {0, 0, -3}};
    const glm::ivec2 size(1920, 1080);
    const Framing f = frame_ring(stone, ring, kDown, size, 45.0, 0.3);
    EXPECT_TRUE(f.ring_cut);
    EXPECT_NEAR(f.stone_share, 0.3, 1e-9);
    for (const glm::dvec3& p : stone) {
        const glm::dvec2 at = ndc_of(p, f, size, 45.0);
        EXPECT_LE(std::abs(at.x), 0.92 + 1e-9);
        EXPECT_LE(std::abs(at.y), 0.92 + 1e-9);
    }
}

TEST(Framing, APortraitPictureFitsTheWidth) {
    // 1080 wide, 1920 high: the 18 mm wide ring needs 18 / 0.92 mm of width, so the height is
    // that times 1920 / 1080.
    const auto stone = square(0.0, 0.0, 3.0);
    const std::vector<glm::dvec3> ring = {{-9, 0, 8}, {9, 0, 8}};
    const glm::ivec2 size(1080, 1920);
    const Framing f = frame_ring(stone, ring, kDown, size, 12.0, 0.1);
    EXPECT_FALSE(f.ring_cut);
    EXPECT_NEAR(ndc_of({9, 0, 8}, f, size, 12.0).x, 0.92, 1e-9);
    EXPECT_NEAR(f.stone_share, 6.0 / (18.0 / 0.92 * 1920.0 / 1080.0), 1e-9);
}

TEST(Framing, ViewZoomScalesTheFramedZoom) {
    Framing f;
    f.zoom = 2.5;
    f.shift = {0.1, 0.4};
    ViewState v = kDown;
    v.zoom = 1.5;
    const CameraSettings s = framed_camera(v, f);
    EXPECT_DOUBLE_EQ(s.zoom, 3.75);
    EXPECT_EQ(s.shift, f.shift);
}

}  // namespace
}  // namespace gem::kiosk
