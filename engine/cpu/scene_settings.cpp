#include "cpu/scene_settings.hpp"

namespace gem {

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
