// Background and lighting presets as the file gives them: file order, hand-checked values,
// image paths resolved against the config's folder, and the built-in sets when the file has
// none.
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "settings/kiosk_config.hpp"

namespace gem::kiosk {
namespace {

constexpr const char* kPresets = R"(
[[background]]
name = "showroom"
kind = "image"
file = "backgrounds/showroom.HDR"
intensity = 0.75

[[background]]
name = "sky"
kind = "image"
file = "/usr/share/gemkiosk/sky.png"

[[background]]
name = "grey"
kind = "uniform"
colour = [0.5, 0.25, 0.125]

[[background]]
name = "white"
kind = "uniform"

[[background]]
name = "black"
kind = "colour"

[[lighting]]
name = "pair"
environment_intensity = 0.5
[[lighting.light]]
position = [10, 20.5, -30]
colour = [3, 2, 1]
[[lighting.light]]
direction = [0, 1, 0]

[[lighting]]
name = "dark"
environment_intensity = 0
)";

TEST(PresetParse, BackgroundsKeepFileOrderAndValues) {
    const ConfigLoad load = parse_config(kPresets, "p.toml", "/etc/gemkiosk");
    ASSERT_TRUE(load.errors.empty()) << load.errors.front();
    const std::vector<BackgroundPreset>& b = load.config.backgrounds;
    ASSERT_EQ(b.size(), 5u);
    using Kind = BackgroundPreset::Kind;

    EXPECT_EQ(b[0].name, "showroom");
    EXPECT_EQ(b[0].kind, Kind::image);
    EXPECT_EQ(b[0].file, "/etc/gemkiosk/backgrounds/showroom.HDR");
    EXPECT_EQ(b[0].intensity, 0.75);

    EXPECT_EQ(b[1].name, "sky");
    EXPECT_EQ(b[1].file, "/usr/share/gemkiosk/sky.png");
    EXPECT_EQ(b[1].intensity, 1.0);

    EXPECT_EQ(b[2].name, "grey");
    EXPECT_EQ(b[2].kind, Kind::uniform);
    EXPECT_EQ(b[2].colour, glm::dvec3(0.5, 0.25, 0.125));
    EXPECT_TRUE(b[2].file.empty());

    // Without a colour: a uniform surround is white, a flat background near-black.
    EXPECT_EQ(b[3].colour, glm::dvec3(1.0));
    EXPECT_EQ(b[4].kind, Kind::colour);
    EXPECT_EQ(b[4].colour, glm::dvec3(0.05));
}

TEST(PresetParse, LightingsKeepFileOrderAndValues) {
    const ConfigLoad load = parse_config(kPresets, "p.toml", "/etc/gemkiosk");
    ASSERT_TRUE(load.errors.empty()) << load.errors.front();
    const std::vector<LightingPreset>& l = load.config.lightings;
    ASSERT_EQ(l.size(), 2u);
    EXPECT_EQ(l[0].name, "pair");
    EXPECT_EQ(l[0].environment_intensity, 0.5);
    ASSERT_EQ(l[0].lights.size(), 2u);
    EXPECT_EQ(l[0].lights[0].position, glm::dvec3(10.0, 20.5, -30.0));
    EXPECT_FALSE(l[0].lights[0].directional);
    EXPECT_EQ(l[0].lights[0].colour, glm::dvec3(3.0, 2.0, 1.0));
    EXPECT_EQ(l[0].lights[1].position, glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_TRUE(l[0].lights[1].directional);
    EXPECT_EQ(l[0].lights[1].colour, glm::dvec3(1.0));
    EXPECT_EQ(l[1].name, "dark");
    EXPECT_EQ(l[1].environment_intensity, 0.0);
    EXPECT_TRUE(l[1].lights.empty());
}

TEST(PresetParse, AFileWithoutPresetsGetsTheBuiltInSets) {
    const ConfigLoad load = parse_config("[render]\ndepth = 3\n", "p.toml", "");
    ASSERT_TRUE(load.errors.empty());
    const std::vector<BackgroundPreset> backgrounds = default_backgrounds();
    const std::vector<LightingPreset> lightings = default_lightings();
    ASSERT_EQ(load.config.backgrounds.size(), backgrounds.size());
    ASSERT_EQ(load.config.lightings.size(), lightings.size());
    for (std::size_t i = 0; i < backgrounds.size(); ++i) {
        EXPECT_EQ(load.config.backgrounds[i].name, backgrounds[i].name);
    }
    for (std::size_t i = 0; i < lightings.size(); ++i) {
        EXPECT_EQ(load.config.lightings[i].name, lightings[i].name);
    }
}

TEST(PresetParse, OneKindGivenLeavesTheOtherBuiltIn) {
    const ConfigLoad load =
        parse_config("[[background]]\nname = \"only\"\n", "p.toml", "/etc/gemkiosk");
    ASSERT_TRUE(load.errors.empty());
    ASSERT_EQ(load.config.backgrounds.size(), 1u);
    EXPECT_EQ(load.config.backgrounds[0].name, "only");
    EXPECT_EQ(load.config.backgrounds[0].kind, BackgroundPreset::Kind::studio);
    EXPECT_EQ(load.config.lightings.size(), default_lightings().size());
}

TEST(PresetParse, BuiltInSetsAreUsableAsTheyStand) {
    const std::vector<BackgroundPreset> backgrounds = default_backgrounds();
    const std::vector<LightingPreset> lightings = default_lightings();
    EXPECT_GE(backgrounds.size(), 3u);
    EXPECT_GE(lightings.size(), 3u);
    std::set<std::string> names;
    for (const BackgroundPreset& b : backgrounds) {
        EXPECT_TRUE(names.insert(b.name).second) << b.name;
        EXPECT_NE(b.kind, BackgroundPreset::Kind::image) << b.name;  // no file ships with them
        EXPECT_GE(glm::min(b.colour.x, glm::min(b.colour.y, b.colour.z)), 0.0) << b.name;
    }
    names.clear();
    for (const LightingPreset& l : lightings) {
        EXPECT_TRUE(names.insert(l.name).second) << l.name;
        EXPECT_LE(l.lights.size(), kMaxPresetLights) << l.name;
        for (const PresetLight& light : l.lights) {
            EXPECT_GT(glm::length(light.position), 0.0) << l.name;
        }
    }
}

}  // namespace
}  // namespace gem::kiosk
