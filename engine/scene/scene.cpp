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

}  // namespace gem
