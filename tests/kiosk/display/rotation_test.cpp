// Rotation maths. Expected values by hand: the kernel's panel orientation names say which
// side of the panel faces up (drm_connector.c), and turning a sheet of paper clockwise by a
// quarter sends its top-left corner to the top-right, top-right to bottom-right, and so on.

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "display/rotation.hpp"

namespace gem::kiosk {
namespace {

TEST(Rotation, PanelOrientationTurnsThePictureBack) {
    EXPECT_EQ(panel_orientation_deg(PanelOrientation::normal), 0);
    EXPECT_EQ(panel_orientation_deg(PanelOrientation::upside_down), 180);
    // Right side up: the panel sits a quarter turn counter-clockwise, the picture turns a
    // quarter clockwise to stand upright.
    EXPECT_EQ(panel_orientation_deg(PanelOrientation::right_side_up), 90);
    EXPECT_EQ(panel_orientation_deg(PanelOrientation::left_side_up), 270);
}

TEST(Rotation, ConfiguredRotationAddsUp) {
    EXPECT_EQ(total_rotation_deg(PanelOrientation::right_side_up, 90).value(), 180);
    EXPECT_EQ(total_rotation_deg(PanelOrientation::left_side_up, 180).value(), 90);
    EXPECT_EQ(total_rotation_deg(PanelOrientation::normal, -90).value(), 270);
    EXPECT_EQ(total_rotation_deg(PanelOrientation::upside_down, 540).value(), 0);
    auto bad = total_rotation_deg(PanelOrientation::normal, 45);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().find("45"), std::string::npos);
}

TEST(Rotation, PictureSizeSwapsAtQuarterTurns) {
    // The 1200x1920 DSI panel of tests/fixtures/drm/portrait_dsi.txt, mounted landscape.
    EXPECT_EQ(picture_size_for({1200, 1920}, 90), glm::ivec2(1920, 1200));
    EXPECT_EQ(picture_size_for({1200, 1920}, 270), glm::ivec2(1920, 1200));
    EXPECT_EQ(picture_size_for({1200, 1920}, 180), glm::ivec2(1200, 1920));
    EXPECT_EQ(picture_size_for({1200, 1920}, 0), glm::ivec2(1200, 1920));
}

// The centre of pixel (x, y), y counted down from the top, in GL's y-up pixel coordinates of
// an image `height` pixels tall.
glm::vec2 centre(int x, int y, int height) {
    return {x + 0.5f, height - 1 - y + 0.5f};
}

TEST(Rotation, CornersLandWherePaperTurnsThem) {
    const int w = 4;  // picture 4x3
    const int h = 3;
    struct Case {
        int rotation;
        // Where the picture's top-left, top-right, bottom-right and bottom-left pixels land
        // on the scanout (y down), and the scanout's size.
        glm::ivec2 tl, tr, br, bl, scanout;
    };
    const Case cases[] = {
        {0, {0, 0}, {3, 0}, {3, 2}, {0, 2}, {4, 3}},
        {90, {2, 0}, {2, 3}, {0, 3}, {0, 0}, {3, 4}},
        {180, {3, 2}, {0, 2}, {0, 0}, {3, 0}, {4, 3}},
        {270, {0, 3}, {0, 0}, {2, 0}, {2, 3}, {3, 4}},
    };
    for (const Case& c : cases) {
        const PictureFromScanout map = picture_from_scanout(c.rotation, {w, h});
        auto picture_at = [&](glm::ivec2 s) {
            return map.linear * centre(s.x, s.y, c.scanout.y) + map.offset;
        };
        EXPECT_EQ(picture_at(c.tl), centre(0, 0, h)) << c.rotation;
        EXPECT_EQ(picture_at(c.tr), centre(w - 1, 0, h)) << c.rotation;
        EXPECT_EQ(picture_at(c.br), centre(w - 1, h - 1, h)) << c.rotation;
        EXPECT_EQ(picture_at(c.bl), centre(0, h - 1, h)) << c.rotation;
        EXPECT_EQ(picture_size_for(c.scanout, c.rotation), glm::ivec2(w, h));
    }
}

// The scanout rectangle of a picture rectangle, against every scanout pixel's own lookup
// (picture_from_scanout, as the present pass samples): a scanout pixel is in the rectangle
// exactly when the picture pixel it shows is.
TEST(Rotation, AScanoutRectangleHoldsExactlyThePixelsShowingThePictureRectangle) {
    const glm::ivec2 picture(7, 5);
    const gpu::PixelRect rect{1, 2, 4, 5};
    for (int rotation : {0, 90, 180, 270}) {
        const glm::ivec2 scanout = picture_size_for(picture, rotation);
        const PictureFromScanout map = picture_from_scanout(rotation, picture);
        const gpu::PixelRect got = scanout_rect(rect, rotation, picture);
        for (int y = 0; y < scanout.y; ++y) {
            for (int x = 0; x < scanout.x; ++x) {
                const glm::vec2 p = map.linear * glm::vec2(x + 0.5f, y + 0.5f) + map.offset;
                const bool shows = p.x > rect.x0 && p.x < rect.x1 && p.y > rect.y0 && p.y < rect.y1;
                const bool inside = x >= got.x0 && x < got.x1 && y >= got.y0 && y < got.y1;
                EXPECT_EQ(shows, inside) << rotation << "°, scanout pixel " << x << ", " << y;
            }
        }
    }
    EXPECT_TRUE(scanout_rect({}, 90, picture).empty());
}

}  // namespace
}  // namespace gem::kiosk
