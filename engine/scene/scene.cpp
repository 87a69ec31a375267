#include "scene/scene.hpp"

#include "import/load_model.hpp"
#include "scene/scene_build.hpp"

namespace gem {

Scene default_scene() {
    // A Tolkowsky round brilliant in diamond, face-up and tilted a little toward the viewer,
    // in the studio: what a shopper sees first.
    Scene scene;
    scene.stone.cut = default_cut_params(CutShape::round_brilliant);
    scene.material.name = "diamond";
    scene.camera.azimuth_deg = 0.0;
    scene.camera.elevation_deg = 75.0;
    scene.camera.zoom = 0.92;  // a little margin around the girdle
    // One point light up and behind the viewer's left shoulder: its tiny highlights in the
    // exit rays are the stone's sparkle.
    scene.lights.push_back({.position = {-30.0, 80.0, 45.0}, .colour = glm::dvec3(2.0)});
    scene.h = 200.0;
    return scene;
}

Result<Material> resolve_material(const MaterialChoice& choice) {
    std::optional<Material> found = find_material(choice.name);
    if (!found) return Error{"material.name: unknown material '" + choice.name + "'"};
    Material m = *found;
    if (choice.index || choice.dispersion) {
        const double nd = choice.index.value_or(m.index(kFraunhoferD));
        m.dispersion = choice.dispersion ? Dispersion::cauchy_from_nd(nd, *choice.dispersion)
                                         : Dispersion::constant_index(nd);
    }
    if (choice.colour) m.body_colour = *choice.colour;
    if (choice.absorption_per_mm) m.absorption_per_mm = *choice.absorption_per_mm;
    return m;
}

Result<Stone> build_stone(const Scene& scene) {
    Result<Material> material = resolve_material(scene.material);
    if (!material) return Error{material.error()};
    if (!scene.stone.model.empty()) {
        ImportOptions options;
        options.material = material.value();
        options.width_mm = scene.stone.model_width_mm;
        return load_model(scene.stone.model, options);
    }
    return make_cut(scene.stone.cut, material.value());
}

Result<Environment> build_environment(const Scene& scene) {
    switch (scene.environment.kind) {
        case EnvironmentChoice::Kind::studio:
            return Environment::studio();
        case EnvironmentChoice::Kind::uniform:
            return Environment::uniform(scene.environment.colour);
        case EnvironmentChoice::Kind::image:
            break;
    }
    return Environment::load_image(scene.environment.file);
}

RenderSettings render_settings(const Scene& scene) {
    RenderSettings s;
    s.width = scene.width;
    s.height = scene.height;
    s.samples_per_pixel = scene.samples_per_pixel;
    s.camera = scene.camera;
    s.shading.model = scene.thesis_weights ? ShadingModel::thesis : ShadingModel::physical;
    s.shading.k_s = scene.k_s;
    s.shading.k_st = scene.k_st;
    s.shading.h = scene.h;
    s.shading.alpha = scene.alpha;
    s.shading.lights = scene.lights;
    s.trace.max_depth = scene.depth;
    s.trace.min_weight = scene.min_weight;
    s.trace.weights = scene.thesis_weights ? WeightModel::thesis_factors : WeightModel::fresnel;
    s.trace.r_factor = scene.r_factor;
    s.trace.t_factor = scene.t_factor;
    s.spectral = scene.spectral;
    s.spectral_samples = scene.spectral_samples;
    s.background_is_environment = scene.environment.background_is_environment;
    s.background_colour = scene.environment.background_colour;
    return s;
}

}  // namespace gem
