// Output selection against connector lists recorded on real machines (tests/fixtures/drm/).
// Expected indices are read off the recordings by hand; expected refresh rates are computed
// by hand from the recorded timings or are modetest's own printed values.

#include <gtest/gtest.h>

#include "connector_fixture.hpp"
#include "display/drm_select.hpp"

namespace gem::kiosk {
namespace {

using test::read_recorded_connectors;

DisplayOptions options_for(const std::string& connector, const std::string& mode) {
    DisplayOptions options;
    options.connector = connector;
    options.mode = mode;
    return options;
}

TEST(ModeRefresh, AgreesWithModetestOnEveryRecordedProgressiveMode) {
    int checked = 0;
    for (const char* file : {"laptop_edp_dp.txt", "hdmi_interlaced.txt", "portrait_dsi.txt"}) {
        const auto recorded = read_recorded_connectors(file);
        for (std::size_t c = 0; c < recorded.connectors.size(); ++c) {
            const auto& modes = recorded.connectors[c].modes;
            for (std::size_t m = 0; m < modes.size(); ++m) {
                // modetest prints two decimals of clock*1000/(htot*vtot), frames not fields;
                // the kernel's rate for an interlaced mode is the field rate, twice that.
                const double factor = modes[m].interlaced ? 2.0 : 1.0;
                EXPECT_NEAR(mode_refresh_hz(modes[m]), factor * recorded.printed_refresh[c][m],
                            factor * 0.005 + 1e-9)
                    << file << " " << recorded.connectors[c].name << " mode " << m;
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 19 + 29 + 1);
}

TEST(ModeRefresh, HandComputedValues) {
    const auto laptop = read_recorded_connectors("laptop_edp_dp.txt");
    ASSERT_EQ(laptop.connectors.size(), 3u);
    // eDP-1: 553250 kHz / (2720 * 1695) = 553250000 / 4610400 = 120.000434 Hz.
    EXPECT_NEAR(mode_refresh_hz(laptop.connectors[0].modes[0]), 120.000434, 1e-6);
    const auto hdmi = read_recorded_connectors("hdmi_interlaced.txt");
    ASSERT_EQ(hdmi.connectors.size(), 1u);
    // 1920x1080i: 74250 kHz / (2200 * 1125) = 30 frames/s = 60 fields/s.
    EXPECT_DOUBLE_EQ(mode_refresh_hz(hdmi.connectors[0].modes[9]), 60.0);
    EXPECT_TRUE(hdmi.connectors[0].modes[9].interlaced);
}

TEST(ModeRefresh, DoubleScanAndVscanDivide) {
    // 640x480 VGA timings (25.2 MHz, 800 x 525 total = 60 Hz), scanned twice, then 4 times.
    ModeInfo mode;
    mode.hdisplay = 640;
    mode.vdisplay = 480;
    mode.clock_khz = 25200;
    mode.htotal = 800;
    mode.vtotal = 525;
    EXPECT_DOUBLE_EQ(mode_refresh_hz(mode), 60.0);
    mode.doublescan = true;
    EXPECT_DOUBLE_EQ(mode_refresh_hz(mode), 30.0);
    mode.vscan = 2;
    EXPECT_DOUBLE_EQ(mode_refresh_hz(mode), 15.0);
    mode.htotal = 0;
    EXPECT_EQ(mode_refresh_hz(mode), 0.0);
}

TEST(ConnectorName, MatchesTheKernelNamesInTheRecordings) {
    // Type numbers from drm_mode.h: DisplayPort 10, HDMIA 11, eDP 14, DSI 16.
    EXPECT_EQ(connector_name(10, 1), "DP-1");
    EXPECT_EQ(connector_name(10, 2), "DP-2");
    EXPECT_EQ(connector_name(11, 1), "HDMI-A-1");
    EXPECT_EQ(connector_name(14, 1), "eDP-1");
    EXPECT_EQ(connector_name(16, 1), "DSI-1");
    EXPECT_EQ(connector_name(9999, 3), "Unknown9999-3");
}

TEST(ChooseOutput, LaptopDefaultsToTheFirstConnectedPanelAtItsPreferredMode) {
    const auto laptop = read_recorded_connectors("laptop_edp_dp.txt");
    auto choice = choose_output(laptop.connectors, DisplayOptions{});
    ASSERT_TRUE(choice) << choice.error();
    EXPECT_EQ(laptop.connectors[choice.value().connector].name, "eDP-1");
    EXPECT_EQ(choice.value().mode, 0u);
}

TEST(ChooseOutput, WithoutAPreferredModeTakesTheLargestAtTheHighestRefresh) {
    // DP-1 marks no mode preferred; its largest is 1920x1080, listed at 60.00 (#0, #1),
    // 59.94 and 50.00: the first 60 Hz one.
    const auto laptop = read_recorded_connectors("laptop_edp_dp.txt");
    auto choice = choose_output(laptop.connectors, options_for("DP-1", ""));
    ASSERT_TRUE(choice) << choice.error();
    EXPECT_EQ(choice.value().connector, 1u);
    EXPECT_EQ(choice.value().mode, 0u);
}

TEST(ChooseOutput, NamedModesPickTheNearestRefresh) {
    const auto laptop = read_recorded_connectors("laptop_edp_dp.txt");
    // DP-1's 1280x720 modes: #8 60.00, #9 59.94, #10 50.00, #11 48.00, #12 47.95.
    const std::pair<const char*, std::size_t> cases[] = {
        {"1280x720", 8},     {"1280x720@60", 8},    {"1280x720@59.94", 9},
        {"1280x720@50", 10}, {"1280x720@48", 11},   {"1280x720@47.95", 12},
        {"1920x1080@50", 3}, {"640x480@59.94", 17}, {"1024x768", 13}};
    for (const auto& [mode, expected] : cases) {
        auto choice = choose_output(laptop.connectors, options_for("DP-1", mode));
        ASSERT_TRUE(choice) << mode << ": " << choice.error();
        EXPECT_EQ(choice.value().mode, expected) << mode;
    }
}

TEST(ChooseOutput, InterlacedModesOnlyWhenAskedFor) {
    const auto hdmi = read_recorded_connectors("hdmi_interlaced.txt");
    auto progressive = choose_output(hdmi.connectors, options_for("", "1920x1080@50"));
    ASSERT_TRUE(progressive) << progressive.error();
    EXPECT_EQ(progressive.value().mode, 3u);
    // This driver lists 1920x1080i with vdisplay 540; the mode name still finds it. Two
    // modes at 60 fields/s (#9, #10): the first.
    auto interlaced = choose_output(hdmi.connectors, options_for("", "1920x1080i"));
    ASSERT_TRUE(interlaced) << interlaced.error();
    EXPECT_EQ(interlaced.value().mode, 9u);
    auto pal = choose_output(hdmi.connectors, options_for("HDMI-A-1", "1920x1080i@50"));
    ASSERT_TRUE(pal) << pal.error();
    EXPECT_EQ(pal.value().mode, 12u);
    auto preferred = choose_output(hdmi.connectors, DisplayOptions{});
    ASSERT_TRUE(preferred) << preferred.error();
    EXPECT_EQ(preferred.value().mode, 0u);
}

TEST(ChooseOutput, PortraitPanelKeepsItsOrientation) {
    const auto dsi = read_recorded_connectors("portrait_dsi.txt");
    auto choice = choose_output(dsi.connectors, DisplayOptions{});
    ASSERT_TRUE(choice) << choice.error();
    const ConnectorInfo& c = dsi.connectors[choice.value().connector];
    EXPECT_EQ(c.name, "DSI-1");
    EXPECT_EQ(c.orientation, PanelOrientation::right_side_up);
    EXPECT_EQ(c.modes[choice.value().mode].hdisplay, 1200);
    EXPECT_EQ(c.modes[choice.value().mode].vdisplay, 1920);
}

TEST(ChooseOutput, UnknownConnectorListsWhatExists) {
    const auto laptop = read_recorded_connectors("laptop_edp_dp.txt");
    auto choice = choose_output(laptop.connectors, options_for("HDMI-A-1", ""));
    ASSERT_FALSE(choice);
    EXPECT_NE(choice.error().find("'HDMI-A-1' does not exist"), std::string::npos)
        << choice.error();
    EXPECT_NE(choice.error().find("eDP-1 (connected), DP-1 (connected), DP-2 (disconnected)"),
              std::string::npos)
        << choice.error();
}

TEST(ChooseOutput, DisconnectedConnectorIsRefused) {
    const auto laptop = read_recorded_connectors("laptop_edp_dp.txt");
    auto choice = choose_output(laptop.connectors, options_for("DP-2", ""));
    ASSERT_FALSE(choice);
    EXPECT_NE(choice.error().find("'DP-2' has nothing connected"), std::string::npos)
        << choice.error();
}

TEST(ChooseOutput, NothingConnected) {
    // The laptop recording with its panel and monitor unplugged.
    auto laptop = read_recorded_connectors("laptop_edp_dp.txt");
    for (ConnectorInfo& c : laptop.connectors) {
        c.connected = false;
        c.modes.clear();
    }
    auto choice = choose_output(laptop.connectors, DisplayOptions{});
    ASSERT_FALSE(choice);
    EXPECT_EQ(choice.error(),
              "no connected display; connectors: eDP-1 (disconnected), DP-1 (disconnected), "
              "DP-2 (disconnected)");
    auto none = choose_output({}, DisplayOptions{});
    ASSERT_FALSE(none);
    EXPECT_EQ(none.error(), "no connected display; connectors: none");
}

TEST(ChooseOutput, MissingModeListsTheConnectorsModes) {
    const auto laptop = read_recorded_connectors("laptop_edp_dp.txt");
    auto choice = choose_output(laptop.connectors, options_for("eDP-1", "1920x1080@60"));
    ASSERT_FALSE(choice);
    EXPECT_EQ(choice.error(),
              "display mode '1920x1080@60' is not offered by eDP-1; modes: "
              "2560x1600@120.00 (preferred)");
    auto far = choose_output(laptop.connectors, options_for("DP-1", "1280x720@75"));
    ASSERT_FALSE(far);
    EXPECT_NE(far.error().find("1280x720@60.00, 1280x720@59.94"), std::string::npos) << far.error();
}

TEST(ParseModeRequest, AcceptsTheDocumentedForms) {
    auto plain = parse_mode_request("1920x1080");
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain.value().width, 1920);
    EXPECT_EQ(plain.value().height, 1080);
    EXPECT_FALSE(plain.value().interlaced);
    EXPECT_FALSE(plain.value().refresh_hz.has_value());
    auto full = parse_mode_request("1920x1080i@59.94");
    ASSERT_TRUE(full);
    EXPECT_TRUE(full.value().interlaced);
    EXPECT_DOUBLE_EQ(*full.value().refresh_hz, 59.94);
}

TEST(ParseModeRequest, RejectsOtherText) {
    for (const char* text : {"", "1920", "1920x", "x1080", "1920x1080@", "1920x1080@abc",
                             "1920x1080p", "1920x1080@60Hz", "0x1080", "1920x1080@-60"}) {
        auto request = parse_mode_request(text);
        ASSERT_FALSE(request) << text;
        EXPECT_NE(request.error().find(std::string("'") + text + "'"), std::string::npos)
            << request.error();
    }
}

}  // namespace
}  // namespace gem::kiosk
