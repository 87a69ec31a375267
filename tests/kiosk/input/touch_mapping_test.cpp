// TouchMapping: the panel's four native corners for every rotation, worked out by hand from
// "the panel scans out the picture turned R clockwise" (see touch_mapping.hpp), and libinput
// calibration matrices.

#include "input/touch_mapping.hpp"

#include <gtest/gtest.h>

namespace gem::kiosk {
namespace {

void expect_maps(const TouchMapping& mapping, glm::dvec2 native, glm::dvec2 picture) {
    const glm::dvec2 mapped = mapping.to_picture(native);
    EXPECT_NEAR(mapped.x, picture.x, 1e-9) << "native (" << native.x << ", " << native.y << ")";
    EXPECT_NEAR(mapped.y, picture.y, 1e-9) << "native (" << native.x << ", " << native.y << ")";
}

// A landscape 800x480 panel. Native corners: TL (0, 0), TR (1, 0), BR (1, 1), BL (0, 1).
TEST(TouchMapping, Rotation0IsAScale) {
    const TouchMapping mapping(identity_calibration, 0, {800, 480});
    expect_maps(mapping, {0, 0}, {0, 0});
    expect_maps(mapping, {1, 0}, {800, 0});
    expect_maps(mapping, {1, 1}, {800, 480});
    expect_maps(mapping, {0, 1}, {0, 480});
    expect_maps(mapping, {0.25, 0.5}, {200, 240});
}

TEST(TouchMapping, Rotation90) {
    // The picture (portrait, 480x800) turned 90 degrees clockwise onto the panel: its top edge
    // lies along the panel's right edge, so its top-left corner is at the panel's top-right,
    // its top-right at the panel's bottom-right, and so on round.
    const TouchMapping mapping(identity_calibration, 90, {480, 800});
    expect_maps(mapping, {1, 0}, {0, 0});      // panel TR shows picture TL
    expect_maps(mapping, {1, 1}, {480, 0});    // panel BR shows picture TR
    expect_maps(mapping, {0, 1}, {480, 800});  // panel BL shows picture BR
    expect_maps(mapping, {0, 0}, {0, 800});    // panel TL shows picture BL
    // Along the panel's top edge, left to right, is the picture's left edge, bottom to top.
    expect_maps(mapping, {0.25, 0}, {0, 600});
}

TEST(TouchMapping, Rotation180) {
    const TouchMapping mapping(identity_calibration, 180, {800, 480});
    expect_maps(mapping, {0, 0}, {800, 480});
    expect_maps(mapping, {1, 0}, {0, 480});
    expect_maps(mapping, {1, 1}, {0, 0});
    expect_maps(mapping, {0, 1}, {800, 0});
    expect_maps(mapping, {0.25, 0}, {600, 480});
}

TEST(TouchMapping, Rotation270) {
    // Turned 270 clockwise (90 anticlockwise): picture TL at panel BL, TR at panel TL, BR at
    // panel TR, BL at panel BR.
    const TouchMapping mapping(identity_calibration, 270, {480, 800});
    expect_maps(mapping, {0, 1}, {0, 0});
    expect_maps(mapping, {0, 0}, {480, 0});
    expect_maps(mapping, {1, 0}, {480, 800});
    expect_maps(mapping, {1, 1}, {0, 800});
    // Along the panel's top edge, left to right, is the picture's right edge, top to bottom.
    expect_maps(mapping, {0.25, 0}, {480, 200});
}

TEST(TouchMapping, CalibrationMatrixOnNormalisedCoordinates) {
    // The touch layer reads only the middle half of the panel: x' = 0.5 x + 0.25, same for y.
    const TouchMapping half(CalibrationMatrix{0.5, 0.0, 0.25, 0.0, 0.5, 0.25}, 0, {800, 480});
    expect_maps(half, {0, 0}, {200, 120});
    expect_maps(half, {1, 1}, {600, 360});
    expect_maps(half, {1, 0}, {600, 120});

    // Swapped axes, libinput's {0 1 0 1 0 0}: x' = y, y' = x.
    const TouchMapping swapped(CalibrationMatrix{0.0, 1.0, 0.0, 1.0, 0.0, 0.0}, 0, {800, 480});
    expect_maps(swapped, {1, 0}, {0, 480});
    expect_maps(swapped, {0.25, 0.75}, {600, 120});
}

TEST(TouchMapping, CalibrationComesBeforeRotation) {
    // Mirror x ({-1 0 1 0 1 0}), then turn 90: native TL -> (1, 0) calibrated, which the
    // rotation sends to the picture's TL (see Rotation90: panel TR shows picture TL).
    const TouchMapping mapping(CalibrationMatrix{-1.0, 0.0, 1.0, 0.0, 1.0, 0.0}, 90, {480, 800});
    expect_maps(mapping, {0, 0}, {0, 0});
    expect_maps(mapping, {1, 1}, {480, 800});
}

TEST(TouchMapping, RotationFromOptions) {
    EXPECT_EQ(touch_rotation_from_options(-1, 90).value(), 90);
    EXPECT_EQ(touch_rotation_from_options(270, 0).value(), 270);
    EXPECT_EQ(touch_rotation_from_options(-90, 0).value(), 270);
    EXPECT_EQ(touch_rotation_from_options(360, 90).value(), 0);
    const Result<int> bad = touch_rotation_from_options(45, 0);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("45"), std::string::npos);
}

}  // namespace
}  // namespace gem::kiosk
