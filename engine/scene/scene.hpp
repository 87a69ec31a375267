#pragma once
// A scene to render: which stone (a parametric cut or a model file) in which material, seen
// by which camera, in which environment and lights, with which weight model and image
// settings. Loaded from one small TOML file (config/scenes/README.md lists every key).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/cuts.hpp"
#include "picture/camera.hpp"
#include "scene/lights.hpp"
#include "util/result.hpp"

namespace gem {

struct StoneSource {
    // The model file, when set, replaces the cut (paths in a scene file are relative to it).
    std::filesystem::path model;
    double model_width_mm = 0.0;  // 0: the file's own size
    CutParams cut = default_cut_params(CutShape::round_brilliant);
};

struct MaterialChoice {
    std::string name = "diamond";  // a built-in material (find_material)
    // Overrides: a constant index, or with `dispersion` a Cauchy fit through n(D) and n(G)−n(B).
    std::optional<double> index;
    std::optional<double> dispersion;
    std::optional<glm::dvec3> colour;             // the thesis' stone colour I_o
    std::optional<glm::dvec3> absorption_per_mm;  // Beer–Lambert σ per channel
};

struct EnvironmentChoice {
    enum class Kind { studio, uniform, image };
    Kind kind = Kind::studio;
    glm::dvec3 colour{1.0};      // uniform
    std::filesystem::path file;  // image
    bool background_is_environment = true;
    glm::dvec3 background_colour{0.0};
};

struct Scene {
    StoneSource stone;
    MaterialChoice material;
    CameraSettings camera{.azimuth_deg = 0.0, .elevation_deg = 75.0};
    EnvironmentChoice environment;
    std::vector<Light> lights;  // at most kMaxLights
    // Shading: "physical" (Fresnel, Beer–Lambert) or "thesis" (R/T factors, k_s, h, α).
    bool thesis_weights = false;
    double k_s = 1.0;
    double k_st = 1.0;
    double h = 60.0;
    double alpha = 0.8;
    double r_factor = 0.3;
    double t_factor = 0.7;
    int depth = 12;
    double min_weight = 1e-4;
    int width = 512;
    int height = 512;
    int samples_per_pixel = 4;
    bool spectral = false;
    int spectral_samples = 12;
};

// The built-in default: config/scenes/default.toml says the same.
Scene default_scene();

// Errors name the file, the line and the key: "scene.toml:7: camera.elevation: expected a
// number". Unknown keys are errors. Relative paths are made relative to the file's folder.
Result<Scene> load_scene(const std::filesystem::path& path);
// The same from text; `name` stands for the file in messages, `base` resolves relative paths.
Result<Scene> parse_scene(std::string_view text, const std::string& name,
                          const std::filesystem::path& base = {});

// The material the scene asks for (built-in entry plus overrides).
Result<Material> resolve_material(const MaterialChoice& choice);

}  // namespace gem
