#pragma once
// The thesis' ray-list for one pixel: the first reflected ray and every ray that leaves the
// stone after internal bounces, each with its exit point, direction, weight and path length.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace gem {

struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit length
};

struct TracedRay {
    glm::dvec3 origin{0.0};     // where it leaves the surface (mm, stone frame)
    glm::dvec3 direction{0.0};  // unit length, pointing away from the stone
    double weight = 0.0;        // product of Fresnel (or thesis R/T-factor) terms along the path
    double path_mm = 0.0;       // length travelled inside the stone (for Beer–Lambert)
    std::uint16_t bounces = 0;  // internal reflections before it left
    std::uint32_t facet = 0;    // facet it left through
};

struct RayList {
    bool hit = false;
    TracedRay reflected;           // first reflection off the entry facet (path_mm = 0)
    std::vector<TracedRay> exits;  // rays that refract out of the stone
    // Energy still inside the stone where the tree was cut (depth or weight threshold);
    // with no absorption, reflected + exits + truncated = 1.
    double truncated_weight = 0.0;

    void clear() {
        hit = false;
        reflected = {};
        exits.clear();
        truncated_weight = 0.0;
    }
};

}  // namespace gem
