#include "gemmology/fire_spread.hpp"

#include <cmath>
#include <numbers>

namespace gem {

namespace {

// Index in `exits` of the first exit at or after `from` that left by the facet of `ray` after
// as many bounces, or -1.
int same_path(const std::vector<TracedRay>& exits, std::size_t from, const TracedRay& ray) {
    for (std::size_t i = from; i < exits.size(); ++i) {
        if (exits[i].facet == ray.facet && exits[i].bounces == ray.bounces) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

}  // namespace

void colour_spread_deg(const RayList& reference, const RayList& red, const RayList& blue,
                       std::vector<double>& out) {
    out.clear();
    std::size_t next_red = 0;
    std::size_t next_blue = 0;
    for (const TracedRay& exit : reference.exits) {
        const int r = same_path(red.exits, next_red, exit);
        const int b = same_path(blue.exits, next_blue, exit);
        if (r >= 0) next_red = static_cast<std::size_t>(r) + 1;
        if (b >= 0) next_blue = static_cast<std::size_t>(b) + 1;
        if (r < 0 || b < 0) {
            out.push_back(-1.0);
            continue;
        }
        // atan2 of |cross| and dot keeps small angles exact, where acos of a dot near 1 does not.
        const glm::dvec3& u = red.exits[std::size_t(r)].direction;
        const glm::dvec3& v = blue.exits[std::size_t(b)].direction;
        out.push_back(std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v)) * 180.0 /
                      std::numbers::pi);
    }
}

}  // namespace gem
