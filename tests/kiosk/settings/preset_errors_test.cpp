// Faults in presets: each is reported with the line the fixture text puts it on, and the
// preset keeps what is usable (a default for the faulty key).
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "fixture_lines.hpp"
#include "settings/kiosk_config.hpp"

namespace gem::kiosk {
namespace {

std::string at(std::string_view text, std::string_view needle, int nth) {
    return "p.toml:" + std::to_string(line_of(text, needle, nth)) + ": ";
}

TEST(PresetErrors, BackgroundFaults) {
    const std::string text =
        "[[background]]\n"
        "kind = \"uniform\"\n"
        "[[background]]\n"
        "name = \"a\"\n"
        "kind = \"image\"\n"
        "[[background]]\n"
        "name = \"a\"\n"
        "kind = \"image\"\n"
        "file = \"sky.jpg\"\n"
        "[[background]]\n"
        "name = \"c\"\n"
        "kind = \"colour\"\n"
        "file = \"sky.png\"\n"
        "[[background]]\n"
        "name = \"d\"\n"
        "kind = \"studio\"\n"
        "colour = [1, 0, 0]\n"
        "[[background]]\n"
        "name = \"e\"\n"
        "kind = \"sunset\"\n"
        "colour = [1, -1, 0]\n"
        "intensity = -2\n"
        "glow = 1\n";
    const ConfigLoad load = parse_config(text, "p.toml", "/etc/gemkiosk");
    const std::vector<std::string> expected = {
        at(text, "[[background]]", 1) + "background.name: missing; called \"background 1\"",
        at(text, "[[background]]", 2) +
            "background.file: kind \"image\" needs a file; shown as \"studio\"",
        at(text, "name = \"a\"", 2) +
            "background.name: \"a\" names an earlier background too; called \"background 3\"",
        at(text, "sky.jpg", 1) + "background.file: expected a PNG (.png) or Radiance (.hdr) image",
        at(text, "sky.png", 1) + "background.file: only kind \"image\" uses a file",
        at(text, "colour = [1, 0, 0]", 1) +
            "background.colour: only kinds \"uniform\", \"colour\" and \"tent\" use a colour",
        at(text, "sunset", 1) +
            "background.kind: expected one of \"studio\", \"uniform\", \"colour\", \"image\", "
            "\"tent\"",
        at(text, "[1, -1, 0]", 1) + "background.colour: colour components must not be negative",
        at(text, "intensity", 1) + "background.intensity: must be between 0 and 1000",
        at(text, "glow", 1) + "background.glow: unknown key",
    };
    EXPECT_EQ(load.errors, expected);
    const std::vector<BackgroundPreset>& b = load.config.backgrounds;
    ASSERT_EQ(b.size(), 6u);  // every table stays a preset
    using Kind = BackgroundPreset::Kind;
    EXPECT_EQ(b[0].name, "background 1");
    EXPECT_EQ(b[0].kind, Kind::uniform);
    EXPECT_EQ(b[1].name, "a");
    EXPECT_EQ(b[1].kind, Kind::studio);
    EXPECT_EQ(b[2].name, "background 3");
    EXPECT_EQ(b[2].kind, Kind::studio);  // its only file was refused
    EXPECT_EQ(b[3].kind, Kind::colour);
    EXPECT_TRUE(b[3].file.empty());
    EXPECT_EQ(b[4].colour, glm::dvec3(0.05));
    EXPECT_EQ(b[5].kind, Kind::studio);
    EXPECT_EQ(b[5].intensity, 1.0);
}

TEST(PresetErrors, LightFaults) {
    const std::string text =
        "[[lighting]]\n"
        "name = \"many\"\n"
        "[[lighting.light]]\n"
        "position = [1, 2, 3]\n"
        "direction = [0, 1, 0]\n"
        "[[lighting.light]]\n"
        "colour = [2, 2, 2]\n"
        "[[lighting.light]]\n"
        "direction = [0, 0, 0]\n"
        "[[lighting.light]]\n"
        "position = [1, 2]\n"
        "intensity = 3\n"
        "[[lighting.light]]\n"
        "position = [5, 5, 5]\n"
        "[[lighting]]\n"
        "name = \"many\"\n"
        "environment_intensity = \"bright\"\n"
        "light = 4\n";
    const ConfigLoad load = parse_config(text, "p.toml", "");
    const std::vector<std::string> expected = {
        at(text, "direction = [0, 1, 0]", 1) +
            "lighting.light.direction: a light has a position or a direction, not both; the "
            "position is used",
        at(text, "[[lighting.light]]", 2) +
            "lighting.light: needs a position or a direction; placed at [0, 100, 0]",
        at(text, "direction = [0, 0, 0]", 1) + "lighting.light.direction: must not be [0, 0, 0]",
        at(text, "position = [1, 2]", 1) +
            "lighting.light.position: expected a list of 3 finite numbers",
        at(text, "intensity = 3", 1) + "lighting.light.intensity: unknown key",
        at(text, "[[lighting.light]]", 5) +
            "lighting.light: at most 4 lights in a preset; this one is left out",
        at(text, "name = \"many\"", 2) +
            "lighting.name: \"many\" names an earlier lighting too; called \"lighting 2\"",
        at(text, "bright", 1) + "lighting.environment_intensity: expected a finite number",
        at(text, "light = 4", 1) + "lighting.light: expected [[lighting.light]] tables",
    };
    EXPECT_EQ(load.errors, expected);
    const std::vector<LightingPreset>& l = load.config.lightings;
    ASSERT_EQ(l.size(), 2u);
    ASSERT_EQ(l[0].lights.size(), 4u);
    EXPECT_EQ(l[0].lights[0].position, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_FALSE(l[0].lights[0].directional);
    EXPECT_EQ(l[0].lights[1].position, glm::dvec3(0.0, 100.0, 0.0));
    EXPECT_EQ(l[0].lights[1].colour, glm::dvec3(2.0));
    EXPECT_EQ(l[0].lights[2].position, glm::dvec3(0.0, 100.0, 0.0));
    EXPECT_FALSE(l[0].lights[2].directional);
    EXPECT_EQ(l[1].name, "lighting 2");
    EXPECT_EQ(l[1].environment_intensity, 1.0);
    EXPECT_TRUE(l[1].lights.empty());
}

TEST(PresetErrors, PresetKeysGivenPlainValuesAreReported) {
    const std::string text = "background = 3\nlighting = { name = \"x\" }\n";
    const ConfigLoad load = parse_config(text, "p.toml", "");
    const std::vector<std::string> expected = {
        at(text, "background", 1) + "background: expected [[background]] tables",
        at(text, "lighting", 1) + "lighting: expected [[lighting]] tables",
    };
    EXPECT_EQ(load.errors, expected);
    EXPECT_EQ(load.config.backgrounds.size(), default_backgrounds().size());
    EXPECT_EQ(load.config.lightings.size(), default_lightings().size());
}

}  // namespace
}  // namespace gem::kiosk
