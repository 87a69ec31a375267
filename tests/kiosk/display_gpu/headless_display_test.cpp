// The headless backend: its frame pacing contract (ready, present, the timer fd) on a real
// EGL surfaceless context. No timing is asserted, only that a due frame eventually comes.

#include <gtest/gtest.h>

#include <poll.h>

#include "display/headless_display.hpp"
#include "display/open_display.hpp"

namespace gem::kiosk {
namespace {

DisplayOptions headless(int width, int height, double rate_hz) {
    DisplayOptions options;
    options.backend = "headless";
    options.headless_width = width;
    options.headless_height = height;
    options.headless_rate_hz = rate_hz;
    return options;
}

TEST(HeadlessDisplay, UnpacedIsAlwaysReady) {
    auto display = HeadlessDisplay::make(headless(64, 48, 0.0));
    ASSERT_TRUE(display) << display.error();
    HeadlessDisplay& d = *display.value();
    EXPECT_EQ(d.picture_size(), glm::ivec2(64, 48));
    EXPECT_EQ(d.rotation_deg(), 0);
    EXPECT_EQ(d.event_fd(), -1);
    EXPECT_EQ(d.timeout_ms(), 0);
    EXPECT_EQ(d.describe(), "headless 64x48 unpaced");
    auto picture = gpu::RenderTarget::make(64, 48);
    ASSERT_TRUE(picture) << picture.error();
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(d.ready());
        ASSERT_TRUE(d.present(picture.value(), gpu::TileSet{}));
    }
    EXPECT_TRUE(d.ready());
    EXPECT_EQ(d.presented(), 3);
}

TEST(HeadlessDisplay, PacedFrameComesFromTheTimer) {
    auto display = HeadlessDisplay::make(headless(32, 16, 200.0));
    ASSERT_TRUE(display) << display.error();
    HeadlessDisplay& d = *display.value();
    EXPECT_EQ(d.describe(), "headless 32x16 200 Hz");
    EXPECT_DOUBLE_EQ(d.refresh_hz(), 200.0);
    ASSERT_GE(d.event_fd(), 0);
    auto picture = gpu::RenderTarget::make(32, 16);
    ASSERT_TRUE(picture) << picture.error();
    ASSERT_TRUE(d.ready());  // the first frame is due at once
    ASSERT_TRUE(d.present(picture.value(), gpu::TileSet{}));
    EXPECT_FALSE(d.ready());
    for (int frame = 0; frame < 3; ++frame) {
        pollfd fd{d.event_fd(), POLLIN, 0};
        // Generous: a 5 ms timer on a loaded machine; the point is that it fires at all.
        ASSERT_EQ(poll(&fd, 1, 5000), 1);
        d.dispatch();
        ASSERT_TRUE(d.ready());
        ASSERT_TRUE(d.present(picture.value(), gpu::TileSet{}));
        EXPECT_FALSE(d.ready());
    }
    EXPECT_EQ(d.presented(), 4);
}

TEST(HeadlessDisplay, PictureOfTheWrongSizeIsRefused) {
    auto display = HeadlessDisplay::make(headless(32, 16, 0.0));
    ASSERT_TRUE(display) << display.error();
    auto picture = gpu::RenderTarget::make(16, 32);
    ASSERT_TRUE(picture) << picture.error();
    auto presented = display.value()->present(picture.value(), gpu::TileSet{});
    ASSERT_FALSE(presented);
    EXPECT_EQ(presented.error(), "headless display: picture is 16x32, the display 32x16");
    EXPECT_EQ(display.value()->presented(), 0);
}

TEST(OpenDisplay, HeadlessBackend) {
    auto display = open_display(headless(20, 10, 30.0));
    ASSERT_TRUE(display) << display.error();
    EXPECT_EQ(display.value()->describe(), "headless 20x10 30 Hz");
    EXPECT_EQ(display.value()->picture_size(), glm::ivec2(20, 10));
    EXPECT_FALSE(display.value()->context().description().empty());
}

}  // namespace
}  // namespace gem::kiosk
