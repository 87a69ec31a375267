// The shipped config/gemkiosk.toml: it loads cleanly, it says what the built-in defaults are
// (so its documentation cannot drift from the code), and it names and documents every key
// the loader knows, counting its switched-off "#key = value" examples.
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "settings/kiosk_config.hpp"

namespace gem::kiosk {
namespace {

const std::filesystem::path kShipped =
    std::filesystem::path(GEM_SOURCE_DIR) / "config/gemkiosk.toml";

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string trim(std::string s) {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    const auto last = s.find_last_not_of(" \t");
    return s.substr(first, last - first + 1);
}

// A switched-off example is "#" directly followed by TOML ("#key = 1", "#[[background]]");
// prose comments have a space after the "#".
bool is_example(const std::string& line) {
    return line.size() > 1 && line[0] == '#' && line[1] != ' ' && line[1] != '#';
}

bool is_prose(const std::string& line) {
    return line.rfind("# ", 0) == 0 || line == "#";
}

// The shipped text with its examples switched on.
std::string with_examples(const std::string& text) {
    std::istringstream in(text);
    std::string out, line;
    while (std::getline(in, line)) out += (is_example(line) ? line.substr(1) : line) + "\n";
    return out;
}

// Walks the file's lines as the shipped file writes them (one key per line, headers
// "[table]" / "[[array]]") and gives, for each dotted key, whether its first occurrence is
// documented: a prose comment on the line above, or one at the end of its own line.
std::map<std::string, bool> documented_keys(const std::string& text) {
    std::map<std::string, bool> keys;
    std::istringstream in(text);
    std::string raw, previous, table;
    while (std::getline(in, raw)) {
        const std::string line = is_example(raw) ? raw.substr(1) : raw;
        std::string key;
        if (line.rfind("[[", 0) == 0) {
            table = line.substr(2, line.find("]]") - 2);
            key = table;
        } else if (line.rfind("[", 0) == 0) {
            table = line.substr(1, line.find(']') - 1);
        } else if (!line.empty() && line[0] != '#' && line.find('=') != std::string::npos) {
            const std::string name = trim(line.substr(0, line.find('=')));
            key = table.empty() ? name : table + "." + name;
        }
        if (!key.empty() && keys.count(key) == 0) {
            keys[key] = is_prose(previous) || line.find(" # ") != std::string::npos;
        }
        previous = raw;
    }
    return keys;
}

TEST(ConfigShipped, LoadsWithoutErrors) {
    ASSERT_TRUE(std::filesystem::exists(kShipped));
    const ConfigLoad load = load_config(kShipped);
    EXPECT_TRUE(load.errors.empty()) << load.errors.front();
}

TEST(ConfigShipped, WithItsExamplesSwitchedOnItStillLoadsWithoutErrors) {
    const std::string text = with_examples(read_text(kShipped));
    const ConfigLoad load = parse_config(text, "gemkiosk.toml", "/etc/gemkiosk");
    EXPECT_TRUE(load.errors.empty()) << load.errors.front();
    // The image example adds a fifth background, with its file beside the config.
    ASSERT_EQ(load.config.backgrounds.size(), default_backgrounds().size() + 1);
    EXPECT_EQ(load.config.backgrounds.back().file, "/etc/gemkiosk/backgrounds/showroom.hdr");
}

TEST(ConfigShipped, NamesAndDocumentsEveryKnownKey) {
    const std::map<std::string, bool> keys = documented_keys(read_text(kShipped));
    const std::vector<std::string> known = known_config_keys();
    // Counted by hand from config/README.md: 2 top-level keys, display 10, input 4, gestures
    // 12, attract 6, render 7, picture 11, catalogue 6, designs 8, snapshot 2, background 5,
    // lighting 4, lighting.light 3.
    EXPECT_EQ(known.size(), 80u);
    for (const std::string& key : known) {
        const auto found = keys.find(key);
        if (found == keys.end()) {
            ADD_FAILURE() << key << " does not appear in " << kShipped;
            continue;
        }
        EXPECT_TRUE(found->second) << key << " has no comment on the line above it";
    }
}

TEST(ConfigShipped, KnownKeysAreUniqueAndIncludeTheNestedOnes) {
    const std::vector<std::string> known = known_config_keys();
    const std::set<std::string> unique(known.begin(), known.end());
    EXPECT_EQ(unique.size(), known.size());
    for (const char* key : {"log_level", "display.rotation", "attract.idle_s", "snapshot.dir",
                            "background.file", "lighting.light", "lighting.light.direction"}) {
        EXPECT_EQ(unique.count(key), 1u) << key;
    }
}

// The shipped values are the built-in defaults, field by field.
TEST(ConfigShipped, StatesTheBuiltInDefaults) {
    const ConfigLoad load = load_config(kShipped);
    ASSERT_TRUE(load.errors.empty()) << load.errors.front();  // else these are the defaults
    const KioskConfig& s = load.config;
    const KioskConfig d;
    EXPECT_EQ(s.log_level, d.log_level);
    EXPECT_EQ(s.crossfade_s, d.crossfade_s);

    EXPECT_EQ(s.display.backend, d.display.backend);
    EXPECT_EQ(s.display.device, d.display.device);
    EXPECT_EQ(s.display.connector, d.display.connector);
    EXPECT_EQ(s.display.mode, d.display.mode);
    EXPECT_EQ(s.display.rotation_deg, d.display.rotation_deg);
    EXPECT_EQ(s.display.atomic, d.display.atomic);
    EXPECT_EQ(s.display.flip_timeout_ms, d.display.flip_timeout_ms);
    EXPECT_EQ(s.display.headless_width, d.display.headless_width);
    EXPECT_EQ(s.display.headless_height, d.display.headless_height);
    EXPECT_EQ(s.display.headless_rate_hz, d.display.headless_rate_hz);

    EXPECT_EQ(s.input.device_dir, d.input.device_dir);
    EXPECT_EQ(s.input.devices, d.input.devices);
    EXPECT_EQ(s.input.calibration, d.input.calibration);
    EXPECT_EQ(s.input.rotation_deg, d.input.rotation_deg);

    const GestureOptions& sg = s.gestures;
    const GestureOptions& dg = d.gestures;
    EXPECT_EQ(sg.degrees_per_picture_height, dg.degrees_per_picture_height);
    EXPECT_EQ(sg.inertia_half_life_s, dg.inertia_half_life_s);
    EXPECT_EQ(sg.min_zoom, dg.min_zoom);
    EXPECT_EQ(sg.max_zoom, dg.max_zoom);
    EXPECT_EQ(sg.wheel_zoom_step, dg.wheel_zoom_step);
    EXPECT_EQ(sg.tap, dg.tap);
    EXPECT_EQ(sg.two_finger_tap, dg.two_finger_tap);
    EXPECT_EQ(sg.tap_max_s, dg.tap_max_s);
    EXPECT_EQ(sg.tap_max_move_px, dg.tap_max_move_px);
    EXPECT_EQ(sg.idle_s, dg.idle_s);
    EXPECT_EQ(sg.attract_deg_per_s, dg.attract_deg_per_s);
    EXPECT_EQ(sg.attract_preset_s, dg.attract_preset_s);
    EXPECT_EQ(sg.attract_stone_s, dg.attract_stone_s);
    EXPECT_EQ(sg.attract_elevation_deg, dg.attract_elevation_deg);
    EXPECT_EQ(sg.attract_ease_s, dg.attract_ease_s);
    EXPECT_EQ(sg.fling_window_s, dg.fling_window_s);
    EXPECT_EQ(sg.fling_min_deg_per_s, dg.fling_min_deg_per_s);
    EXPECT_EQ(sg.fling_max_deg_per_s, dg.fling_max_deg_per_s);

    EXPECT_EQ(s.render.method, d.render.method);
    EXPECT_EQ(s.render.blend, d.render.blend);
    EXPECT_EQ(s.render.cube_face, d.render.cube_face);
    EXPECT_EQ(s.render.depth, d.render.depth);
    EXPECT_EQ(s.render.view_cache_mb, d.render.view_cache_mb);
    EXPECT_EQ(s.render.frame_rate_hz, d.render.frame_rate_hz);
    EXPECT_EQ(s.render.auto_headroom, d.render.auto_headroom);
    EXPECT_EQ(s.picture.msaa, d.picture.msaa);
    EXPECT_EQ(s.picture.glare, d.picture.glare);
    EXPECT_EQ(s.picture.tone, d.picture.tone);
    EXPECT_EQ(s.picture.exposure_ev, d.picture.exposure_ev);
    EXPECT_EQ(s.picture.stone_share, d.picture.stone_share);
    EXPECT_EQ(s.picture.still_frames, d.picture.still_frames);
    EXPECT_EQ(s.picture.spectral_stills, d.picture.spectral_stills);
    EXPECT_EQ(s.picture.still_depth, d.picture.still_depth);
    EXPECT_EQ(s.picture.still_seconds, d.picture.still_seconds);
    EXPECT_EQ(s.picture.still_depth_max, d.picture.still_depth_max);
    EXPECT_EQ(s.picture.still_frame_ms, d.picture.still_frame_ms);

    EXPECT_EQ(s.catalogue.default_dir, d.catalogue.default_dir);
    EXPECT_EQ(s.catalogue.state_dir, d.catalogue.state_dir);
    EXPECT_EQ(s.catalogue.inbox_dir, d.catalogue.inbox_dir);
    EXPECT_EQ(s.catalogue.watch_dirs, d.catalogue.watch_dirs);
    EXPECT_EQ(s.catalogue.settle_s, d.catalogue.settle_s);
    EXPECT_EQ(s.catalogue.trusted_keys, d.catalogue.trusted_keys);
    EXPECT_EQ(s.designs.tables, d.designs.tables);
    EXPECT_EQ(s.designs.builder, d.designs.builder);
    EXPECT_EQ(s.designs.level_px, d.designs.level_px);
    EXPECT_EQ(s.designs.spacing_deg, d.designs.spacing_deg);
    EXPECT_EQ(s.designs.depth, d.designs.depth);
    EXPECT_EQ(s.designs.threshold, d.designs.threshold);
    EXPECT_EQ(s.designs.memory_mb, d.designs.memory_mb);
    EXPECT_EQ(s.designs.jobs, d.designs.jobs);
    EXPECT_EQ(s.snapshot.dir, d.snapshot.dir);
    EXPECT_EQ(s.snapshot.every_n_frames, d.snapshot.every_n_frames);

    ASSERT_EQ(s.backgrounds.size(), d.backgrounds.size());
    for (std::size_t i = 0; i < d.backgrounds.size(); ++i) {
        EXPECT_EQ(s.backgrounds[i].name, d.backgrounds[i].name);
        EXPECT_EQ(s.backgrounds[i].kind, d.backgrounds[i].kind) << d.backgrounds[i].name;
        EXPECT_EQ(s.backgrounds[i].colour, d.backgrounds[i].colour) << d.backgrounds[i].name;
        EXPECT_EQ(s.backgrounds[i].file, d.backgrounds[i].file) << d.backgrounds[i].name;
        EXPECT_EQ(s.backgrounds[i].intensity, d.backgrounds[i].intensity) << d.backgrounds[i].name;
    }
    ASSERT_EQ(s.lightings.size(), d.lightings.size());
    for (std::size_t i = 0; i < d.lightings.size(); ++i) {
        const LightingPreset& sl = s.lightings[i];
        const LightingPreset& dl = d.lightings[i];
        EXPECT_EQ(sl.name, dl.name);
        EXPECT_EQ(sl.environment_intensity, dl.environment_intensity) << dl.name;
        EXPECT_EQ(sl.exposure_ev, dl.exposure_ev) << dl.name;
        ASSERT_EQ(sl.lights.size(), dl.lights.size()) << dl.name;
        for (std::size_t j = 0; j < dl.lights.size(); ++j) {
            EXPECT_EQ(sl.lights[j].position, dl.lights[j].position) << dl.name;
            EXPECT_EQ(sl.lights[j].directional, dl.lights[j].directional) << dl.name;
            EXPECT_EQ(sl.lights[j].colour, dl.lights[j].colour) << dl.name;
        }
    }
}

}  // namespace
}  // namespace gem::kiosk
