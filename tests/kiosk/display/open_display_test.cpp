// The factory's answers where there is no screen: unknown backends, card discovery over a
// scratch directory, and this machine's missing /dev/dri (no root, GPU or DRM needed).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "display/open_display.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;

fs::path scratch_dir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("gem_display_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(OpenDisplay, UnknownBackendIsNamed) {
    DisplayOptions options;
    options.backend = "fbdev";
    auto display = open_display(options);
    ASSERT_FALSE(display);
    EXPECT_EQ(display.error(), "display backend 'fbdev': expected drm or headless");
}

TEST(DrmCards, FoundInNumberOrderSkippingOtherNodes) {
    const fs::path dir = scratch_dir("cards");
    for (const char* name : {"card10", "renderD128", "card2", "card0", "cardX"}) {
        std::ofstream(dir / name) << "";
    }
    fs::create_directory(dir / "by-path");
    auto cards = drm_card_candidates("", dir.string());
    ASSERT_TRUE(cards) << cards.error();
    const std::vector<std::string> expected = {(dir / "card0").string(), (dir / "card2").string(),
                                               (dir / "card10").string()};
    EXPECT_EQ(cards.value(), expected);
    fs::remove_all(dir);
}

TEST(DrmCards, EmptyDirectoryIsAnError) {
    const fs::path dir = scratch_dir("empty");
    auto cards = drm_card_candidates("", dir.string());
    ASSERT_FALSE(cards);
    EXPECT_EQ(cards.error(), "no DRM card: " + dir.string() + " has no card* node (tried " +
                                 dir.string() + "/card*)");
    fs::remove_all(dir);
}

TEST(DrmCards, MissingDirectoryNamesItAndTheReason) {
    auto cards = drm_card_candidates("", "/nonexistent/dri");
    ASSERT_FALSE(cards);
    EXPECT_NE(cards.error().find("/nonexistent/dri"), std::string::npos) << cards.error();
    EXPECT_NE(cards.error().find("No such file or directory"), std::string::npos) << cards.error();
}

TEST(DrmCards, NamedDeviceMustExist) {
    auto cards = drm_card_candidates("/nonexistent/dri/card7");
    ASSERT_FALSE(cards);
    EXPECT_EQ(cards.error(), "/nonexistent/dri/card7: No such file or directory");
}

TEST(OpenDisplay, DrmWithoutDevDriFailsWithOneClearMessage) {
    if (fs::exists("/dev/dri")) GTEST_SKIP() << "this machine has /dev/dri";
    DisplayOptions options;  // backend "drm", first card
    auto display = open_display(options);
    ASSERT_FALSE(display);
    EXPECT_EQ(display.error(),
              "DRM display: no DRM card: /dev/dri: No such file or directory (tried "
              "/dev/dri/card*; is a GPU driver loaded?)");
    options.device = "/dev/dri/card0";
    auto named = open_display(options);
    ASSERT_FALSE(named);
    EXPECT_EQ(named.error(), "DRM display: /dev/dri/card0: No such file or directory");
}

TEST(OpenDisplay, HeadlessOptionsAreCheckedBeforeAnyEgl) {
    DisplayOptions options;
    options.backend = "headless";
    options.headless_width = 0;
    auto small = open_display(options);
    ASSERT_FALSE(small);
    EXPECT_EQ(small.error(), "headless display: size 0x1080 must be at least 1x1");
    options.headless_width = 640;
    options.headless_rate_hz = -1.0;
    auto negative = open_display(options);
    ASSERT_FALSE(negative);
    EXPECT_NE(negative.error().find("must be 0 (unpaced) or more"), std::string::npos)
        << negative.error();
}

}  // namespace
}  // namespace gem::kiosk
