// The kernel's mode struct to the selection's ModeInfo, with the numbers of the recorded
// 1920x1080i mode of tests/fixtures/drm/hdmi_interlaced.txt and the bits of drm_mode.h.

#include <gtest/gtest.h>

#include <cstring>

#include "display/drm_probe.hpp"

namespace gem::kiosk {
namespace {

drmModeModeInfo recorded_interlaced_mode() {
    drmModeModeInfo m{};
    m.clock = 74250;
    m.hdisplay = 1920;
    m.hsync_start = 2008;
    m.hsync_end = 2052;
    m.htotal = 2200;
    m.vdisplay = 540;
    m.vsync_start = 1084;
    m.vsync_end = 1094;
    m.vtotal = 1125;
    m.flags = DRM_MODE_FLAG_PHSYNC | DRM_MODE_FLAG_PVSYNC | DRM_MODE_FLAG_INTERLACE;
    m.type = DRM_MODE_TYPE_DRIVER;
    std::strcpy(m.name, "1920x1080i");
    return m;
}

TEST(ModeInfoFrom, CarriesTimingsFlagsAndType) {
    drmModeModeInfo m = recorded_interlaced_mode();
    ModeInfo info = mode_info_from(m);
    EXPECT_EQ(info.name, "1920x1080i");
    EXPECT_EQ(info.hdisplay, 1920);
    EXPECT_EQ(info.vdisplay, 540);
    EXPECT_EQ(info.clock_khz, 74250);
    EXPECT_EQ(info.htotal, 2200);
    EXPECT_EQ(info.vtotal, 1125);
    EXPECT_TRUE(info.interlaced);
    EXPECT_FALSE(info.doublescan);
    EXPECT_FALSE(info.preferred);
    // 74.25 MHz / (2200 * 1125) = 30 frames, 60 fields per second.
    EXPECT_DOUBLE_EQ(mode_refresh_hz(info), 60.0);

    m.type |= DRM_MODE_TYPE_PREFERRED;
    m.flags = DRM_MODE_FLAG_DBLSCAN;
    info = mode_info_from(m);
    EXPECT_TRUE(info.preferred);
    EXPECT_FALSE(info.interlaced);
    EXPECT_TRUE(info.doublescan);
    EXPECT_DOUBLE_EQ(mode_refresh_hz(info), 15.0);
}

TEST(ModeInfoFrom, NameFillingTheWholeFieldHasNoTerminator) {
    drmModeModeInfo m = recorded_interlaced_mode();
    std::memset(m.name, 'x', sizeof m.name);  // DRM_DISPLAY_MODE_LEN bytes, no NUL
    EXPECT_EQ(mode_info_from(m).name, std::string(sizeof m.name, 'x'));
}

}  // namespace
}  // namespace gem::kiosk
