// Scene files: every key read back, and mistakes (unknown keys, wrong types, unknown names)
// reported with the file, the line and the key.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cpu/scene_settings.hpp"
#include "scene/scene.hpp"
#include "scene/scene_build.hpp"

namespace gem {
namespace {

// Every key set to a value different from the default.
constexpr const char* kFullScene = R"(# a scene with every key
[stone]
cut = "oval"
width_mm = 7.25
length_to_width = 1.4
table_pct = 55.5
crown_angle_deg = 33
pavilion_angle_deg = 41.5
girdle_pct = 3
star_pct = 45
lower_girdle_pct = 80
culet_pct = 1.5
faceted_girdle = false

[material]
name = "sapphire"
index = 1.77
dispersion = 0.018
colour = [0.1, 0.2, 0.9]
absorption_per_mm = [0.5, 0.25, 0.05]

[camera]
azimuth = 12.5
elevation = 60
roll = -15
zoom = 0.8
perspective_mm = 250

[environment]
kind = "uniform"
colour = [0.5, 0.6, 0.7]
background = [0.1, 0.1, 0.2]

[[light]]
position = [10, 20, 30]
colour = [1, 0.9, 0.8]

[[light]]
direction = [0, 1, 0]
colour = [2, 2, 2]

[shading]
weights = "thesis"
k_s = 0.7
k_st = 0.4
h = 25
alpha = 0.6
r_factor = 0.35
t_factor = 0.65
depth = 7
min_weight = 0.001

[image]
width = 320
height = 240
spp = 9
spectral = true
spectral_samples = 16
)";

void expect_vec(const glm::dvec3& a, const glm::dvec3& b) {
    EXPECT_DOUBLE_EQ(a.x, b.x);
    EXPECT_DOUBLE_EQ(a.y, b.y);
    EXPECT_DOUBLE_EQ(a.z, b.z);
}

TEST(SceneToml, EveryKeyIsRead) {
    Result<Scene> loaded = parse_scene(kFullScene, "full.toml", "/scenes");
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const Scene& s = loaded.value();
    EXPECT_EQ(s.stone.cut.shape, CutShape::oval);
    EXPECT_TRUE(s.stone.model.empty());
    EXPECT_DOUBLE_EQ(s.stone.cut.width_mm, 7.25);
    EXPECT_DOUBLE_EQ(s.stone.cut.length_to_width, 1.4);
    EXPECT_DOUBLE_EQ(s.stone.cut.table_pct, 55.5);
    EXPECT_DOUBLE_EQ(s.stone.cut.crown_angle_deg, 33.0);
    EXPECT_DOUBLE_EQ(s.stone.cut.pavilion_angle_deg, 41.5);
    EXPECT_DOUBLE_EQ(s.stone.cut.girdle_pct, 3.0);
    EXPECT_DOUBLE_EQ(s.stone.cut.star_pct, 45.0);
    EXPECT_DOUBLE_EQ(s.stone.cut.lower_girdle_pct, 80.0);
    EXPECT_DOUBLE_EQ(s.stone.cut.culet_pct, 1.5);
    EXPECT_FALSE(s.stone.cut.faceted_girdle);
    EXPECT_EQ(s.material.name, "sapphire");
    EXPECT_DOUBLE_EQ(s.material.index.value(), 1.77);
    EXPECT_DOUBLE_EQ(s.material.dispersion.value(), 0.018);
    expect_vec(s.material.colour.value(), {0.1, 0.2, 0.9});
    expect_vec(s.material.absorption_per_mm.value(), {0.5, 0.25, 0.05});
    EXPECT_DOUBLE_EQ(s.camera.azimuth_deg, 12.5);
    EXPECT_DOUBLE_EQ(s.camera.elevation_deg, 60.0);
    EXPECT_DOUBLE_EQ(s.camera.roll_deg, -15.0);
    EXPECT_DOUBLE_EQ(s.camera.zoom, 0.8);
    EXPECT_DOUBLE_EQ(s.camera.perspective_distance_mm, 250.0);
    EXPECT_EQ(s.environment.kind, EnvironmentChoice::Kind::uniform);
    expect_vec(s.environment.colour, {0.5, 0.6, 0.7});
    EXPECT_FALSE(s.environment.background_is_environment);
    expect_vec(s.environment.background_colour, {0.1, 0.1, 0.2});
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_FALSE(s.lights[0].directional);
    expect_vec(s.lights[0].position, {10, 20, 30});
    expect_vec(s.lights[0].colour, {1, 0.9, 0.8});
    EXPECT_TRUE(s.lights[1].directional);
    expect_vec(s.lights[1].position, {0, 1, 0});
    expect_vec(s.lights[1].colour, {2, 2, 2});
    EXPECT_TRUE(s.thesis_weights);
    EXPECT_DOUBLE_EQ(s.k_s, 0.7);
    EXPECT_DOUBLE_EQ(s.k_st, 0.4);
    EXPECT_DOUBLE_EQ(s.h, 25.0);
    EXPECT_DOUBLE_EQ(s.alpha, 0.6);
    EXPECT_DOUBLE_EQ(s.r_factor, 0.35);
    EXPECT_DOUBLE_EQ(s.t_factor, 0.65);
    EXPECT_EQ(s.depth, 7);
    EXPECT_DOUBLE_EQ(s.min_weight, 0.001);
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.height, 240);
    EXPECT_EQ(s.samples_per_pixel, 9);
    EXPECT_TRUE(s.spectral);
    EXPECT_EQ(s.spectral_samples, 16);

    // The render settings carry the same values.
    const RenderSettings r = render_settings(s);
    EXPECT_EQ(r.shading.model, ShadingModel::thesis);
    EXPECT_EQ(r.trace.weights, WeightModel::thesis_factors);
    EXPECT_EQ(r.trace.max_depth, 7);
    EXPECT_DOUBLE_EQ(r.trace.r_factor, 0.35);
    EXPECT_EQ(r.shading.lights.size(), 2u);
    EXPECT_EQ(r.width, 320);
}

TEST(SceneToml, ModelAndImagePathsAreRelativeToTheFile) {
    Result<Scene> s = parse_scene(
        "[stone]\nmodel = \"stones/srb.asc\"\nmodel_width_mm = 5\n"
        "[environment]\nkind = \"image\"\nfile = \"/abs/env.hdr\"\n",
        "rel.toml", "/scenes");
    ASSERT_TRUE(s.ok()) << s.error();
    EXPECT_EQ(s.value().stone.model, std::filesystem::path("/scenes/stones/srb.asc"));
    EXPECT_DOUBLE_EQ(s.value().stone.model_width_mm, 5.0);
    EXPECT_EQ(s.value().environment.file, std::filesystem::path("/abs/env.hdr"));
}

TEST(SceneToml, MaterialOverridesApply) {
    MaterialChoice choice;
    choice.name = "quartz";
    choice.index = 1.9;
    choice.colour = glm::dvec3(0.5, 0.5, 1.0);
    Result<Material> m = resolve_material(choice);
    ASSERT_TRUE(m.ok());
    // A constant index: the same at both ends of the spectrum.
    EXPECT_DOUBLE_EQ(m.value().index(kFraunhoferG), 1.9);
    EXPECT_DOUBLE_EQ(m.value().index(kFraunhoferB), 1.9);
    expect_vec(m.value().body_colour, {0.5, 0.5, 1.0});
    choice.dispersion = 0.05;
    Result<Material> dispersive = resolve_material(choice);
    ASSERT_TRUE(dispersive.ok());
    EXPECT_NEAR(dispersive.value().index(kFraunhoferG) - dispersive.value().index(kFraunhoferB),
                0.05, 1e-9);
}

// The message must say which file, which line and which key.
void expect_error(const std::string& text, const std::string& where, const std::string& what) {
    Result<Scene> s = parse_scene(text, "scene.toml");
    ASSERT_FALSE(s.ok()) << "accepted:\n" << text;
    EXPECT_NE(s.error().find(where), std::string::npos) << s.error();
    EXPECT_NE(s.error().find(what), std::string::npos) << s.error();
}

TEST(SceneToml, UnknownKeysAreErrors) {
    expect_error("[camera]\nazimuth = 10\nelevaton = 60\n", "scene.toml:3: camera.elevaton",
                 "unknown key");
    expect_error("\n[stone]\ncut = \"round\"\ntabel_pct = 55\n", "scene.toml:4: stone.tabel_pct",
                 "unknown key");
    expect_error("[cmaera]\nzoom = 2\n", "scene.toml:1: cmaera", "unknown key");
    expect_error("[[light]]\nposition = [0, 9, 0]\nintensity = 2\n",
                 "scene.toml:3: light.intensity", "unknown key");
}

TEST(SceneToml, WrongTypesAreErrors) {
    expect_error("[image]\nwidth = 64\n\n[camera]\nazimuth = 0\nroll = 0\nelevation = \"high\"\n",
                 "scene.toml:7: camera.elevation", "expected a number");
    expect_error("[image]\nspp = 2.5\n", "scene.toml:2: image.spp", "expected an integer");
    expect_error("[image]\nspectral = 1\n", "scene.toml:2: image.spectral", "true or false");
    expect_error("[material]\ncolour = [1, 2]\n", "scene.toml:2: material.colour", "[x, y, z]");
    expect_error("camera = 5\n", "scene.toml:1: camera", "expected a table");
    expect_error("[camera]\nelevation = 120\n", "scene.toml:2: camera.elevation", "between");
    expect_error("[camera]\nazimuth = nan\n", "scene.toml:2: camera.azimuth", "finite");
    expect_error("[[light]]\nposition = [0, inf, 0]\n", "scene.toml:2: light.position", "finite");
}

TEST(SceneToml, UnknownNamesAreErrors) {
    expect_error("# stones\n[stone]\ncut = \"rhombus\"\n", "scene.toml:3: stone.cut",
                 "unknown cut 'rhombus'");
    expect_error("[material]\nname = \"kryptonite\"\n", "scene.toml:2: material.name",
                 "unknown material 'kryptonite'");
    expect_error("[shading]\nweights = \"magic\"\n", "scene.toml:2: shading.weights", "physical");
    expect_error("[environment]\nkind = \"space\"\n", "scene.toml:2: environment.kind", "studio");
}

TEST(SceneToml, SyntaxErrorsAndMissingFilesNameTheFile) {
    expect_error("[camera]\nzoom = = 2\n", "scene.toml:2", "");
    const auto missing = std::filesystem::path(GEM_ARTIFACT_DIR) / "no-such-scene.toml";
    Result<Scene> s = load_scene(missing);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().find("no-such-scene.toml"), std::string::npos) << s.error();
}

TEST(SceneToml, LoadScenePutsThePathInMessages) {
    const auto dir = std::filesystem::path(GEM_ARTIFACT_DIR) / "scene_toml_test";
    std::filesystem::create_directories(dir);
    const auto path = dir / "typo.toml";
    std::ofstream(path) << "[camera]\nzoom = 1\n\n[image]\nsize = 64\n";
    Result<Scene> s = load_scene(path);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().find("typo.toml:5: image.size: unknown key"), std::string::npos)
        << s.error();
}

TEST(SceneToml, DefaultFileIsTheBuiltInDefault) {
    const auto path = std::filesystem::path(GEM_FIXTURES_DIR) / "../../config/scenes/default.toml";
    Result<Scene> loaded = load_scene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const Scene& a = loaded.value();
    const Scene b = default_scene();
    EXPECT_EQ(a.stone.cut.shape, b.stone.cut.shape);
    EXPECT_DOUBLE_EQ(a.stone.cut.width_mm, b.stone.cut.width_mm);
    EXPECT_DOUBLE_EQ(a.stone.cut.table_pct, b.stone.cut.table_pct);
    EXPECT_DOUBLE_EQ(a.stone.cut.crown_angle_deg, b.stone.cut.crown_angle_deg);
    EXPECT_DOUBLE_EQ(a.stone.cut.pavilion_angle_deg, b.stone.cut.pavilion_angle_deg);
    EXPECT_EQ(a.material.name, b.material.name);
    EXPECT_DOUBLE_EQ(a.camera.azimuth_deg, b.camera.azimuth_deg);
    EXPECT_DOUBLE_EQ(a.camera.elevation_deg, b.camera.elevation_deg);
    EXPECT_DOUBLE_EQ(a.camera.zoom, b.camera.zoom);
    EXPECT_EQ(a.environment.kind, b.environment.kind);
    EXPECT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < std::min(a.lights.size(), b.lights.size()); ++i) {
        expect_vec(a.lights[i].position, b.lights[i].position);
        expect_vec(a.lights[i].colour, b.lights[i].colour);
    }
    EXPECT_EQ(a.thesis_weights, b.thesis_weights);
    EXPECT_DOUBLE_EQ(a.h, b.h);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.width, 512);
    EXPECT_EQ(a.height, 512);
    EXPECT_EQ(a.samples_per_pixel, b.samples_per_pixel);
    EXPECT_EQ(a.spectral, b.spectral);
}

}  // namespace
}  // namespace gem
