#include "scene/shading.hpp"

#include "optics/fresnel.hpp"

namespace gem {

Shader::Shader(const Stone& stone, const Material& material, const Environment& environment,
               const ShadingSettings& settings)
    : stone_(stone), material_(material), environment_(environment), settings_(settings) {
    assert(settings.lights.size() <= static_cast<std::size_t>(kMaxLights));
}

glm::dvec3 Shader::light_specular(const TracedRay& ray, double k) const {
    glm::dvec3 sum(0.0);
    if (k == 0.0) return sum;
    for (const Light& light : settings_.lights) {
        const glm::dvec3 to_light = direction_to_light(light, ray.origin);
        const double lobe = specular_lobe(ray.direction, to_light, settings_.h);
        if (lobe == 0.0) continue;
        if (light_blocked(stone_, ray.origin, ray.facet, light, to_light)) continue;
        sum += light.colour * (k * lobe);
    }
    return sum;
}

glm::dvec3 Shader::shade(const RayList& list) const {
    if (!list.hit) return glm::dvec3(0.0);
    return settings_.model == ShadingModel::physical ? shade_physical(list) : shade_thesis(list);
}

glm::dvec3 Shader::shade_physical(const RayList& list) const {
    const TracedRay& r = list.reflected;
    glm::dvec3 colour =
        r.weight * (environment_.radiance(r.direction) + light_specular(r, settings_.k_s));
    for (const TracedRay& e : list.exits) {
        const glm::dvec3 transmittance = beer_lambert(material_.absorption_per_mm, e.path_mm);
        colour += e.weight * transmittance *
                  (environment_.radiance(e.direction) + light_specular(e, settings_.k_st));
    }
    return colour;
}

glm::dvec3 Shader::shade_thesis(const RayList& list) const {
    const glm::dvec3& stone_colour = material_.body_colour;
    const double alpha = settings_.alpha;
    const TracedRay& r = list.reflected;
    glm::dvec3 colour = r.weight * light_specular(r, settings_.k_s);
    colour += r.weight * (environment_.radiance(r.direction) * alpha + stone_colour * (1 - alpha));
    for (const TracedRay& e : list.exits) {
        colour += e.weight * stone_colour * light_specular(e, settings_.k_st);
        colour +=
            e.weight * (environment_.radiance(e.direction) * alpha + stone_colour * (1 - alpha));
    }
    return colour;
}

}  // namespace gem
