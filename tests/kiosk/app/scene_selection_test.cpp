// SceneSelection: stones and presets cycle in order, a stone's own presets come with it, and
// the look handed to the renderer combines the two presets as documented.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "catalogue/validate.hpp"
#include "stage/scene_selection.hpp"

namespace gem::kiosk {
namespace {

BackgroundPreset preset(const char* name, BackgroundPreset::Kind kind, glm::dvec3 colour,
                        double intensity) {
    BackgroundPreset p;
    p.name = name;
    p.kind = kind;
    p.colour = colour;
    p.intensity = intensity;
    return p;
}

std::vector<BackgroundPreset> backgrounds() {
    using K = BackgroundPreset::Kind;
    return {preset("studio", K::studio, glm::dvec3(0.05), 1.0),
            preset("velvet", K::colour, {0.2, 0.0, 0.1}, 0.5),
            preset("sky", K::uniform, {0.5, 0.6, 0.9}, 2.0)};
}

std::vector<LightingPreset> lightings() {
    LightingPreset soft{.name = "soft", .environment_intensity = 1.0, .lights = {}};
    LightingPreset spots{.name = "spots",
                         .environment_intensity = 0.5,
                         .lights = {{.position = {0, 100, 50}, .colour = {3, 3, 3}}}};
    return {soft, spots};
}

CatalogueStone stone(const char* name, const char* background = "", const char* lighting = "") {
    CatalogueStone s;
    s.name = name;
    s.background = background;
    s.lighting = lighting;
    return s;
}

Catalogue catalogue() {
    Catalogue c;
    c.name = "test";
    c.stones = {stone("a"), stone("b", "sky", "spots"), stone("c")};
    return c;
}

TEST(SceneSelection, StonesCycleInCatalogueOrderAndBringTheirPresets) {
    SceneSelection s(backgrounds(), lightings());
    EXPECT_FALSE(s.has_stone());
    s.set_catalogue(catalogue());
    ASSERT_TRUE(s.has_stone());
    EXPECT_EQ(s.stone().name, "a");
    EXPECT_EQ(s.background().name, "studio");
    s.next_stone();
    EXPECT_EQ(s.stone().name, "b");
    EXPECT_EQ(s.background().name, "sky");  // named by stone b
    EXPECT_EQ(s.lighting().name, "spots");
    s.next_stone();
    EXPECT_EQ(s.stone().name, "c");
    EXPECT_EQ(s.background().name, "sky");  // c names none: the presets stay
    s.next_stone();
    EXPECT_EQ(s.stone().name, "a");  // wraps round
}

// The startup catalogue's first stone, then the whole catalogue (CatalogueCompletion): the stone
// on screen stays where the whole holds the same entry at its place, else the first is shown.
TEST(SceneSelection, AWholeCatalogueKeepsTheStoneOnScreenWhereItHoldsIt) {
    SceneSelection s(backgrounds(), lightings());
    Catalogue first = catalogue();
    first.stones.resize(1);
    first.unchecked = 2;
    s.set_catalogue(first);
    s.next_stone();  // one stone so far: it wraps to itself
    EXPECT_EQ(s.stone().name, "a");
    EXPECT_TRUE(s.complete_catalogue(catalogue()));
    EXPECT_EQ(s.stone().name, "a");
    s.next_stone();
    EXPECT_EQ(s.stone().name, "b");  // the others have joined
    // Shown from another file than the whole catalogue names at that place: not the same.
    Catalogue moved = catalogue();
    moved.stones[1].database = "elsewhere.gemdb";
    EXPECT_FALSE(s.complete_catalogue(moved));
    EXPECT_EQ(s.stone().name, "a");
}

// The stone on screen holds its models, built as it comes (the catalogue holds the first
// entry's only). An entry whose file went away after validation is said once and left out of
// the cycle; the others are shown in order.
TEST(SceneSelection, TheStoneShownHoldsItsModelsAndOneWhoseFileWentIsLeftOut) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(GEM_ARTIFACT_DIR) / "selection-gone";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const auto write = [&](const char* file, const char* text) {
        std::ofstream(dir / file) << text;
    };
    write("catalogue.toml",
          "[catalogue]\nname = \"designs\"\n"
          "[[stone]]\nname = \"a\"\ndesign = \"a.toml\"\n"
          "[[stone]]\nname = \"b\"\ndesign = \"b.toml\"\n"
          "[[stone]]\nname = \"c\"\ndesign = \"c.toml\"\n");
    for (const char* file : {"a.toml", "b.toml", "c.toml"}) {
        write(file, "[stone]\ncut = \"round\"\n[material]\nname = \"diamond\"\n");
    }
    auto validated = validate_catalogue(dir);
    ASSERT_TRUE(validated) << validated.error();
    ASSERT_EQ(validated.value().stones.size(), 3u);
    ASSERT_EQ(validated.value().stones[2].designed, nullptr);
    fs::remove(dir / "b.toml");

    SceneSelection s(backgrounds(), lightings());
    s.set_catalogue(validated.value());
    ASSERT_NE(s.stone().designed, nullptr);
    testing::internal::CaptureStderr();
    s.next_stone();
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_EQ(s.stone().name, "c");
    ASSERT_NE(s.stone().designed, nullptr);
    EXPECT_NE(said.find("catalogue entry 'b': "), std::string::npos) << said;
    EXPECT_NE(said.find("b.toml"), std::string::npos) << said;
    EXPECT_NE(said.find("left out"), std::string::npos) << said;
    EXPECT_EQ(s.describe().rfind("stone 'c' (2/2)", 0), 0u) << s.describe();
    testing::internal::CaptureStderr();
    s.next_stone();
    EXPECT_EQ(s.stone().name, "a");
    s.next_stone();
    EXPECT_EQ(s.stone().name, "c");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << "said once";
}

TEST(SceneSelection, PresetsAdvanceTogetherAndWrap) {
    SceneSelection s(backgrounds(), lightings());
    s.next_preset();
    EXPECT_EQ(s.background().name, "velvet");
    EXPECT_EQ(s.lighting().name, "spots");
    s.next_preset();
    EXPECT_EQ(s.background().name, "sky");
    EXPECT_EQ(s.lighting().name, "soft");  // two lightings: back to the first
}

TEST(SceneSelection, LookCombinesBackgroundAndLighting) {
    SceneSelection s(backgrounds(), lightings());
    s.next_preset();  // velvet (flat colour, intensity 0.5) with spots (environment 0.5)
    LookChoice look = s.look();
    EXPECT_EQ(look.background, LookChoice::Background::colour);
    EXPECT_DOUBLE_EQ(look.background_intensity, 0.5);
    // Behind a flat colour the background's intensity is the colour's alone.
    EXPECT_DOUBLE_EQ(look.environment_intensity, 0.5);
    ASSERT_EQ(look.lights.size(), 1u);
    EXPECT_EQ(look.lights[0].position, glm::dvec3(0, 100, 50));
    s.next_preset();  // sky (uniform, intensity 2) with soft (environment 1)
    look = s.look();
    EXPECT_EQ(look.background, LookChoice::Background::uniform);
    EXPECT_DOUBLE_EQ(look.environment_intensity, 2.0);  // 1 × 2
    EXPECT_TRUE(look.lights.empty());
}

}  // namespace
}  // namespace gem::kiosk
