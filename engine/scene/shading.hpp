#pragma once
// Turns one pixel's ray-list into linear RGB, with either weight model:
//  - physical: each ray's Fresnel weight × Beer–Lambert transmittance exp(-σ·path) ×
//    (environment in the ray's direction + the lights' specular lobes k_s (D·L)^h);
//  - thesis (Lee 2004, eq. 6.2-6.5): I_sr = Σ_l I_l k_s F_r (R·L)^h on the reflected ray,
//    I_st = Σ_n Σ_l I_l I_o k_st F_nt (T_n·L)^h on the exit rays and
//    I_r = Σ_k (I_k α + I_o (1 − α)) F_k over every ray of the list, reflected one included as
//    the thesis writes it; I_o is the stone colour, α the transparency.
// Shading allocates nothing.

#include <vector>

#include <glm/glm.hpp>

#include "geometry/stone.hpp"
#include "scene/environment.hpp"
#include "scene/lights.hpp"
#include "trace/ray_list.hpp"

namespace gem {

enum class ShadingModel { physical, thesis };

struct ShadingSettings {
    ShadingModel model = ShadingModel::physical;
    double k_s = 1.0;    // specular coefficient of the reflected ray
    double k_st = 1.0;   // specular coefficient of the exit rays
    double h = 60.0;     // specular exponent
    double alpha = 1.0;  // thesis: transparency α (1 = the environment only, no stone colour)
    std::vector<Light> lights;  // at most kMaxLights
};

class Shader {
  public:
    // Keeps references: the stone, environment and settings must outlive the shader.
    Shader(const Stone& stone, const Material& material, const Environment& environment,
           const ShadingSettings& settings);

    glm::dvec3 shade(const RayList& list) const;

  private:
    glm::dvec3 light_specular(const TracedRay& ray, double k) const;
    glm::dvec3 shade_physical(const RayList& list) const;
    glm::dvec3 shade_thesis(const RayList& list) const;

    const Stone& stone_;
    Material material_;
    const Environment& environment_;
    const ShadingSettings& settings_;
};

}  // namespace gem
