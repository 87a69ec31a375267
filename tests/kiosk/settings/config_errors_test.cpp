// Every form of config error: each message must carry the file name, the line the fixture
// text itself puts the key on (found by searching the text, not taken from the loader), the
// dotted key and the fault; the faulty key keeps its default and the good keys around it
// still take effect.
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "fixture_lines.hpp"
#include "settings/kiosk_config.hpp"

namespace gem::kiosk {
namespace {

std::string message(std::string_view text, std::string_view needle, std::string_view key,
                    std::string_view what) {
    return "t.toml:" + std::to_string(line_of(text, needle)) + ": " + std::string(key) + ": " +
           std::string(what);
}

TEST(ConfigErrors, SyntaxErrorNamesLineAndColumnAndSetsTheWholeFileAside) {
    const std::string text =
        "[display]\n"
        "rotation = 90\n"
        "backend = \n"
        "[render]\n"
        "depth = 4\n";
    const ConfigLoad load = parse_config(text, "t.toml", "/etc/gemkiosk");
    ASSERT_EQ(load.errors.size(), 1u);
    // "t.toml:3:COLUMN: ...", the column a positive number.
    const std::string& e = load.errors[0];
    ASSERT_EQ(e.rfind("t.toml:3:", 0), 0u) << e;
    const std::size_t column_end = e.find(": ", 9);
    ASSERT_NE(column_end, std::string::npos) << e;
    const std::string column = e.substr(9, column_end - 9);
    EXPECT_FALSE(column.empty()) << e;
    EXPECT_EQ(column.find_first_not_of("0123456789"), std::string::npos) << e;
    EXPECT_NE(column.front(), '0') << e;
    EXPECT_FALSE(load.parsed);
    // Keys before and after the fault are not used either.
    EXPECT_EQ(load.config.display.rotation_deg, 0);
    EXPECT_EQ(load.config.render.depth, 8);
}

TEST(ConfigErrors, DuplicateKeyIsASyntaxError) {
    const std::string text = "[render]\ndepth = 4\ndepth = 5\n";
    const ConfigLoad load = parse_config(text, "t.toml", "");
    ASSERT_EQ(load.errors.size(), 1u);
    EXPECT_EQ(load.errors[0].rfind("t.toml:3:", 0), 0u) << load.errors[0];
    EXPECT_EQ(load.config.render.depth, 8);
}

TEST(ConfigErrors, WrongTypesAreReportedAndKeepDefaults) {
    const std::string text =
        "[display]\n"
        "connector = \"HDMI-A-1\"\n"
        "rotation = \"90\"\n"
        "atomic = \"yes\"\n"
        "headless_width = 1920.5\n"
        "device = 5\n"
        "[input]\n"
        "devices = [\"/dev/input/event3\", 3]\n"
        "calibration = [1, 0, 0]\n"
        "[gestures]\n"
        "min_zoom = \"small\"\n"
        "max_zoom = 4\n";
    const ConfigLoad load = parse_config(text, "t.toml", "");
    const std::vector<std::string> expected = {
        message(text, "rotation =", "display.rotation", "expected one of 0, 90, 180, 270"),
        message(text, "atomic =", "display.atomic", "expected true or false"),
        message(text, "headless_width =", "display.headless_width", "expected an integer"),
        message(text, "device =", "display.device", "expected a string"),
        message(text, "devices =", "input.devices", "expected a list of strings"),
        message(text, "calibration =", "input.calibration", "expected a list of 6 finite numbers"),
        message(text, "min_zoom =", "gestures.min_zoom", "expected a finite number"),
    };
    EXPECT_EQ(load.errors, expected);
    EXPECT_EQ(load.config.display.rotation_deg, 0);
    EXPECT_TRUE(load.config.display.atomic);
    EXPECT_EQ(load.config.display.headless_width, 1920);
    EXPECT_EQ(load.config.display.device, "");
    EXPECT_TRUE(load.config.input.devices.empty());
    EXPECT_EQ(load.config.input.calibration, (std::array<double, 6>{1, 0, 0, 0, 1, 0}));
    EXPECT_EQ(load.config.gestures.min_zoom, 0.6);
    // The good keys beside the bad ones are used.
    EXPECT_EQ(load.config.display.connector, "HDMI-A-1");
    EXPECT_EQ(load.config.gestures.max_zoom, 4.0);
}

TEST(ConfigErrors, ATableKeyGivenAValueIsReported) {
    const std::string text = "log_level = \"debug\"\ndisplay = 3\n";
    const ConfigLoad load = parse_config(text, "t.toml", "");
    EXPECT_EQ(load.errors,
              std::vector<std::string>{message(text, "display =", "display", "expected a table")});
    EXPECT_EQ(load.config.log_level, LogLevel::debug);
}

TEST(ConfigErrors, ValuesOutOfRangeAreReportedAndKeepDefaults) {
    const std::string text =
        "crossfade_s = 20\n"
        "[display]\n"
        "headless_width = 0\n"
        "flip_timeout_ms = -5\n"
        "headless_rate_hz = -1\n"
        "mode = \"1920x\"\n"
        "[gestures]\n"
        "wheel_zoom_step = 0.5\n"
        "[attract]\n"
        "idle_s = nan\n"
        "stone_s = inf\n"
        "[render]\n"
        "cube_face = 8\n"
        "view_cache_mb = 100000\n"
        "[snapshot]\n"
        "every_n_frames = -1\n"
        "[catalogue]\n"
        "inbox_dir = \"\"\n"
        "[designs]\n"
        "level_px = 8\n"
        "memory_mb = 4\n";
    const ConfigLoad load = parse_config(text, "t.toml", "");
    const std::vector<std::string> expected = {
        message(text, "crossfade_s", "crossfade_s", "must be between 0 and 10"),
        message(text, "headless_width", "display.headless_width", "must be between 1 and 16384"),
        message(text, "flip_timeout_ms", "display.flip_timeout_ms", "must be between 1 and 10000"),
        message(text, "headless_rate_hz", "display.headless_rate_hz", "must be between 0 and 1000"),
        message(text, "mode =", "display.mode",
                "expected \"WIDTHxHEIGHT\" or \"WIDTHxHEIGHT@HZ\", e.g. \"1920x1080@60\""),
        message(text, "wheel_zoom_step", "gestures.wheel_zoom_step", "must be between 1 and 10"),
        message(text, "idle_s", "attract.idle_s", "expected a finite number"),
        message(text, "stone_s", "attract.stone_s", "expected a finite number"),
        message(text, "cube_face", "render.cube_face", "must be between 16 and 4096"),
        message(text, "view_cache_mb", "render.view_cache_mb", "must be between 16 and 65536"),
        message(text, "every_n_frames", "snapshot.every_n_frames", "must be between 0 and 1000000"),
        message(text, "inbox_dir", "catalogue.inbox_dir", "expected a path, not an empty string"),
        message(text, "level_px", "designs.level_px", "must be between 16 and 4096"),
        message(text, "memory_mb", "designs.memory_mb", "must be between 16 and 1048576"),
    };
    EXPECT_EQ(load.errors, expected);
    EXPECT_EQ(load.config.crossfade_s, 0.4);
    EXPECT_EQ(load.config.display.headless_width, 1920);
    EXPECT_EQ(load.config.display.flip_timeout_ms, 250);
    EXPECT_EQ(load.config.display.headless_rate_hz, 60.0);
    EXPECT_EQ(load.config.display.mode, "");
    EXPECT_EQ(load.config.gestures.wheel_zoom_step, 1.1);
    EXPECT_EQ(load.config.gestures.idle_s, 60.0);
    EXPECT_EQ(load.config.gestures.attract_stone_s, 60.0);
    EXPECT_EQ(load.config.render.cube_face, 256);
    EXPECT_EQ(load.config.render.view_cache_mb, 256);
    EXPECT_EQ(load.config.snapshot.every_n_frames, 0);
    EXPECT_EQ(load.config.catalogue.inbox_dir, "/var/lib/gemkiosk/inbox");
    EXPECT_EQ(load.config.designs.level_px, 256);
    EXPECT_EQ(load.config.designs.memory_mb, 1024);
}

TEST(ConfigErrors, ModesInBothFormsAreAccepted) {
    for (const char* mode : {"1920x1080", "1280x800@60", ""}) {
        const ConfigLoad load =
            parse_config("[display]\nmode = \"" + std::string(mode) + "\"\n", "t.toml", "");
        EXPECT_TRUE(load.errors.empty()) << mode;
        EXPECT_EQ(load.config.display.mode, mode);
    }
    for (const char* mode : {"1920", "x1080", "1920x1080@", "1920x1080@60Hz", "-1920x1080"}) {
        const ConfigLoad load =
            parse_config("[display]\nmode = \"" + std::string(mode) + "\"\n", "t.toml", "");
        EXPECT_EQ(load.errors.size(), 1u) << mode;
    }
}

TEST(ConfigErrors, UnknownKeysAndTablesAreReported) {
    const std::string text =
        "verbose = true\n"
        "[display]\n"
        "rotaton = 90\n"
        "rotation = 180\n"
        "[displya]\n"
        "backend = \"headless\"\n"
        "[render]\n"
        "method = \"trace\"\n"
        "shadows = true\n";
    const ConfigLoad load = parse_config(text, "t.toml", "");
    const std::vector<std::string> expected = {
        message(text, "verbose", "verbose", "unknown key"),
        message(text, "rotaton", "display.rotaton", "unknown key"),
        message(text, "[displya]", "displya", "unknown key"),
        message(text, "shadows", "render.shadows", "unknown key"),
    };
    EXPECT_EQ(load.errors, expected);
    EXPECT_EQ(load.config.display.rotation_deg, 180);
    EXPECT_EQ(load.config.display.backend, "drm");
    EXPECT_EQ(load.config.render.method, std::string("trace"));
}

TEST(ConfigErrors, UnknownChoicesNameTheChoices) {
    const std::string text =
        "log_level = \"loud\"\n"
        "[display]\n"
        "backend = \"x11\"\n"
        "[input]\n"
        "rotation = 45\n"
        "[gestures]\n"
        "tap = \"double\"\n"
        "two_finger_tap = \"none\"\n"
        "[render]\n"
        "method = \"raster\"\n"
        "[designs]\n"
        "tables = \"sometimes\"\n";
    const ConfigLoad load = parse_config(text, "t.toml", "");
    const std::vector<std::string> expected = {
        message(text, "log_level", "log_level",
                "expected one of \"error\", \"warning\", \"notice\", \"info\", \"debug\""),
        message(text, "backend", "display.backend", "expected one of \"drm\", \"headless\""),
        message(text, "rotation = 45", "input.rotation",
                "expected \"display\" or one of 0, 90, 180, 270"),
        message(text, "tap = \"double\"", "gestures.tap",
                "expected one of \"none\", \"next_stone\", \"next_preset\""),
        message(text, "method", "render.method",
                "expected one of \"trace\", \"table\", \"phong\", \"auto\""),
        message(text, "tables", "designs.tables",
                "expected one of \"auto\", \"always\", \"never\""),
    };
    EXPECT_EQ(load.errors, expected);
    EXPECT_EQ(load.config.log_level, LogLevel::info);
    EXPECT_EQ(load.config.display.backend, "drm");
    EXPECT_EQ(load.config.input.rotation_deg, -1);
    EXPECT_EQ(load.config.gestures.tap, TapAction::next_stone);
    EXPECT_EQ(load.config.gestures.two_finger_tap, TapAction::none);
    EXPECT_EQ(load.config.render.method, std::string("auto"));
    EXPECT_EQ(load.config.designs.tables, DesignTablesMode::automatic);
}

TEST(ConfigErrors, ZoomLimitsOutOfOrderGoBackToTheDefaults) {
    {
        const std::string text = "[gestures]\nmax_zoom = 2\nmin_zoom = 4\n";
        const ConfigLoad load = parse_config(text, "t.toml", "");
        EXPECT_EQ(load.errors,
                  std::vector<std::string>{message(
                      text, "max_zoom", "gestures.max_zoom",
                      "must not be less than gestures.min_zoom; both keep their defaults")});
        EXPECT_EQ(load.config.gestures.min_zoom, 0.6);
        EXPECT_EQ(load.config.gestures.max_zoom, 3.0);
    }
    {
        // Only min_zoom is set, above the default max_zoom of 3: its line is the one to blame.
        const std::string text = "[gestures]\n\nmin_zoom = 5\n";
        const ConfigLoad load = parse_config(text, "t.toml", "");
        ASSERT_EQ(load.errors.size(), 1u);
        EXPECT_EQ(load.errors[0].rfind("t.toml:3: gestures.max_zoom: ", 0), 0u) << load.errors[0];
        EXPECT_EQ(load.config.gestures.min_zoom, 0.6);
    }
    {
        const std::string text = "[gestures]\nmin_zoom = 2\nmax_zoom = 2\n";
        const ConfigLoad load = parse_config(text, "t.toml", "");
        EXPECT_TRUE(load.errors.empty());
        EXPECT_EQ(load.config.gestures.min_zoom, 2.0);
        EXPECT_EQ(load.config.gestures.max_zoom, 2.0);
    }
}

TEST(ConfigErrors, ErrorsComeInLineOrder) {
    // toml++ keeps a table's keys sorted by name; the messages must still follow the file.
    const std::string text = "[render]\nview_cache_mb = 1\ndepth = 0\nblend = 3\n";
    const ConfigLoad load = parse_config(text, "t.toml", "");
    ASSERT_EQ(load.errors.size(), 3u);
    EXPECT_EQ(load.errors[0].rfind("t.toml:2: render.view_cache_mb", 0), 0u);
    EXPECT_EQ(load.errors[1].rfind("t.toml:3: render.depth", 0), 0u);
    EXPECT_EQ(load.errors[2].rfind("t.toml:4: render.blend", 0), 0u);
}

TEST(ConfigErrors, MissingFileIsOneMessageAndNotParsed) {
    const std::filesystem::path file = "/nonexistent-gemkiosk-test/gemkiosk.toml";
    const ConfigLoad load = load_config(file);
    ASSERT_EQ(load.errors.size(), 1u);
    EXPECT_EQ(load.errors[0].rfind(file.string() + ": cannot open (No such file", 0), 0u)
        << load.errors[0];
    EXPECT_FALSE(load.parsed);
    EXPECT_EQ(load.config.display.backend, "drm");
    EXPECT_EQ(load.config.backgrounds.size(), default_backgrounds().size());
}

TEST(ConfigErrors, EmptyTextIsAllDefaultsWithoutErrors) {
    const ConfigLoad load = parse_config("", "t.toml", "");
    EXPECT_TRUE(load.errors.empty());
    EXPECT_EQ(load.config.render.method, std::string("auto"));
    EXPECT_EQ(load.config.log_level, LogLevel::info);
}

}  // namespace
}  // namespace gem::kiosk
