#pragma once
// Point and directional lights, the thesis' specular lobe and the light obstruction test
// (Lee 2004, eq. 6.2-6.3: a light adds nothing where the angle to the ray exceeds 90° or where
// other facets of the stone block it).

#include <glm/glm.hpp>

#include "geometry/stone.hpp"

namespace gem {

inline constexpr int kMaxLights = 4;

struct Light {
    // A point light's position (mm, stone frame), or for a directional light the direction
    // toward the light (any length).
    glm::dvec3 position{0.0, 100.0, 0.0};
    bool directional = false;
    glm::dvec3 colour{1.0};  // linear RGB
};

// Unit direction from point p toward the light.
glm::dvec3 direction_to_light(const Light& light, const glm::dvec3& p);

// The Phong-like lobe (R·L)^h of eq. 6.2, zero beyond 90°.
double specular_lobe(const glm::dvec3& ray_direction, const glm::dvec3& to_light, double h);

// True when the stone itself lies between `p` (a point on facet `facet`) and the light in
// direction `to_light`. For a convex stone only the leaving facet can block (its plane faces
// away from the light); otherwise the ray toward the light is tested against every triangle.
bool light_blocked(const Stone& stone, const glm::dvec3& p, std::uint32_t facet, const Light& light,
                   const glm::dvec3& to_light);

}  // namespace gem
