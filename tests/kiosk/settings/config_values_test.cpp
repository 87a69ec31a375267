// A config that sets every option key to a value other than its default: each must arrive in
// its field. The expected values are the literals of the fixture text.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "settings/kiosk_config.hpp"

namespace gem::kiosk {
namespace {

constexpr const char* kEveryOption = R"(
log_level = "warning"
crossfade_s = 1.5

[display]
backend = "headless"
device = "/dev/dri/card1"
connector = "DP-2"
mode = "1280x800@50"
rotation = 270
atomic = false
flip_timeout_ms = 500
headless_width = 640
headless_height = 480
headless_rate_hz = 0

[input]
device_dir = "/run/test-input"
devices = ["/dev/input/event4", "ILITEK Multi-Touch"]
calibration = [0, 1, 0, -1, 0, 1]
rotation = 90

[gestures]
degrees_per_picture_height = 270
inertia_half_life_s = 0
min_zoom = 0.5
max_zoom = 8
wheel_zoom_step = 1.25
tap = "next_preset"
two_finger_tap = "none"
tap_max_s = 0.4
tap_max_move_px = 20
fling_window_s = 0.12
fling_min_deg_per_s = 5
fling_max_deg_per_s = 400

[attract]
idle_s = 0
deg_per_s = -6.5
preset_s = 0
stone_s = 300
elevation_deg = 55
ease_s = 0

[render]
method = "phong"
blend = true
cube_face = 1024
depth = 12
view_cache_mb = 64
frame_rate_hz = 30
auto_headroom = 0.5

[catalogue]
default_dir = "current"
state_dir = "/srv/kiosk"
inbox_dir = "../drop"
watch_dirs = ["/media/usb", "stick"]
settle_s = 0.5

[designs]
tables = "always"
builder = "bin/gemtables"
level_px = 128
spacing_deg = 4.5
depth = 6
threshold = 0.01
memory_mb = 300
jobs = 1

[snapshot]
dir = "shots"
every_n_frames = 10
)";

TEST(ConfigValues, EveryOptionKeyReachesItsField) {
    const ConfigLoad load = parse_config(kEveryOption, "every.toml", "/etc/gemkiosk");
    EXPECT_TRUE(load.errors.empty()) << load.errors.front();
    const KioskConfig& c = load.config;
    EXPECT_EQ(c.log_level, LogLevel::warning);
    EXPECT_EQ(c.crossfade_s, 1.5);

    EXPECT_EQ(c.display.backend, "headless");
    EXPECT_EQ(c.display.device, "/dev/dri/card1");
    EXPECT_EQ(c.display.connector, "DP-2");
    EXPECT_EQ(c.display.mode, "1280x800@50");
    EXPECT_EQ(c.display.rotation_deg, 270);
    EXPECT_FALSE(c.display.atomic);
    EXPECT_EQ(c.display.flip_timeout_ms, 500);
    EXPECT_EQ(c.display.headless_width, 640);
    EXPECT_EQ(c.display.headless_height, 480);
    EXPECT_EQ(c.display.headless_rate_hz, 0.0);

    EXPECT_EQ(c.input.device_dir, "/run/test-input");
    EXPECT_EQ(c.input.devices,
              (std::vector<std::string>{"/dev/input/event4", "ILITEK Multi-Touch"}));
    EXPECT_EQ(c.input.calibration, (std::array<double, 6>{0, 1, 0, -1, 0, 1}));
    EXPECT_EQ(c.input.rotation_deg, 90);

    EXPECT_EQ(c.gestures.degrees_per_picture_height, 270.0);
    EXPECT_EQ(c.gestures.inertia_half_life_s, 0.0);
    EXPECT_EQ(c.gestures.min_zoom, 0.5);
    EXPECT_EQ(c.gestures.max_zoom, 8.0);
    EXPECT_EQ(c.gestures.wheel_zoom_step, 1.25);
    EXPECT_EQ(c.gestures.tap, TapAction::next_preset);
    EXPECT_EQ(c.gestures.two_finger_tap, TapAction::none);
    EXPECT_EQ(c.gestures.tap_max_s, 0.4);
    EXPECT_EQ(c.gestures.tap_max_move_px, 20.0);
    EXPECT_EQ(c.gestures.idle_s, 0.0);
    EXPECT_EQ(c.gestures.attract_deg_per_s, -6.5);
    EXPECT_EQ(c.gestures.attract_preset_s, 0.0);
    EXPECT_EQ(c.gestures.attract_stone_s, 300.0);
    EXPECT_EQ(c.gestures.attract_elevation_deg, 55.0);
    EXPECT_EQ(c.gestures.attract_ease_s, 0.0);
    EXPECT_EQ(c.gestures.fling_window_s, 0.12);
    EXPECT_EQ(c.gestures.fling_min_deg_per_s, 5.0);
    EXPECT_EQ(c.gestures.fling_max_deg_per_s, 400.0);

    EXPECT_EQ(c.render.method, std::string("phong"));
    EXPECT_TRUE(c.render.blend);
    EXPECT_EQ(c.render.cube_face, 1024);
    EXPECT_EQ(c.render.depth, 12);
    EXPECT_EQ(c.render.view_cache_mb, 64);
    EXPECT_EQ(c.render.frame_rate_hz, 30.0);
    EXPECT_EQ(c.render.auto_headroom, 0.5);

    // Relative paths are the config folder's; absolute ones stay as they are.
    EXPECT_EQ(c.catalogue.default_dir, "/etc/gemkiosk/current");
    EXPECT_EQ(c.catalogue.state_dir, "/srv/kiosk");
    EXPECT_EQ(c.catalogue.inbox_dir, "/etc/gemkiosk/../drop");
    EXPECT_EQ(c.catalogue.watch_dirs,
              (std::vector<std::filesystem::path>{"/media/usb", "/etc/gemkiosk/stick"}));
    EXPECT_EQ(c.catalogue.settle_s, 0.5);
    EXPECT_EQ(c.designs.tables, DesignTablesMode::always);
    EXPECT_EQ(c.designs.builder, "/etc/gemkiosk/bin/gemtables");
    EXPECT_EQ(c.designs.level_px, 128);
    EXPECT_EQ(c.designs.spacing_deg, 4.5);
    EXPECT_EQ(c.designs.depth, 6);
    EXPECT_EQ(c.designs.threshold, 0.01);
    EXPECT_EQ(c.designs.memory_mb, 300);
    EXPECT_EQ(c.designs.jobs, 1);
    EXPECT_EQ(c.snapshot.dir, "/etc/gemkiosk/shots");
    EXPECT_EQ(c.snapshot.every_n_frames, 10);
}

TEST(ConfigValues, InputRotationFollowsTheDisplayByName) {
    const ConfigLoad load = parse_config("[input]\nrotation = \"display\"\n", "t.toml", "");
    EXPECT_TRUE(load.errors.empty());
    EXPECT_EQ(load.config.input.rotation_deg, -1);
}

TEST(ConfigValues, IntegersAreAcceptedForNumberKeys) {
    const ConfigLoad load = parse_config("[gestures]\ntap_max_s = 1\n", "t.toml", "");
    EXPECT_TRUE(load.errors.empty());
    EXPECT_EQ(load.config.gestures.tap_max_s, 1.0);
}

TEST(ConfigValues, LoadConfigResolvesPathsAgainstTheFilesFolder) {
    const std::filesystem::path dir = std::filesystem::path(GEM_ARTIFACT_DIR) / "config_values";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "kiosk.toml";
    {
        std::ofstream out(file);
        out << "[snapshot]\ndir = \"shots\"\n[render]\ndepth = 3\n";
    }
    const ConfigLoad load = load_config(file);
    EXPECT_TRUE(load.errors.empty());
    EXPECT_EQ(load.config.snapshot.dir, dir / "shots");
    EXPECT_EQ(load.config.render.depth, 3);
}

TEST(ConfigValues, LoadConfigNamesTheFileInErrors) {
    const std::filesystem::path dir = std::filesystem::path(GEM_ARTIFACT_DIR) / "config_values";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "bad.toml";
    {
        std::ofstream out(file);
        out << "\n\n[render]\ndepth = 0\n";
    }
    const ConfigLoad load = load_config(file);
    EXPECT_EQ(load.errors, std::vector<std::string>{file.string() +
                                                    ":4: render.depth: must be between 1 and 64"});
}

TEST(ConfigValues, AutoMethodAndHeadroom) {
    const ConfigLoad load =
        parse_config("[render]\nmethod = \"auto\"\nauto_headroom = 0.65\n", "t.toml", "");
    EXPECT_TRUE(load.errors.empty());
    EXPECT_EQ(load.config.render.method, std::string("auto"));
    EXPECT_EQ(load.config.render.auto_headroom, 0.65);
}

TEST(ConfigValues, HeadroomOutOfRangeKeepsItsDefault) {
    const ConfigLoad load = parse_config("[render]\nauto_headroom = 1.5\n", "t.toml", "");
    ASSERT_EQ(load.errors.size(), 1u);
    EXPECT_NE(load.errors.front().find("render.auto_headroom"), std::string::npos);
    EXPECT_EQ(load.config.render.auto_headroom, 0.8);
}

}  // namespace
}  // namespace gem::kiosk
