// A decoded view's pixel back as a ray-list (database_types.hpp).
#include "gemdb/database_types.hpp"

namespace gem {

RayList ray_list_at(const DecodedView& view, std::size_t pixel) {
    RayList list;
    const std::uint32_t first = view.ray_offset[pixel];
    const std::uint32_t end = first + view.ray_count[pixel];
    list.hit = end > first;
    list.truncated_weight = view.truncated_weight[pixel];
    for (std::uint32_t r = first; r < end; ++r) {
        const TracedRay ray{glm::dvec3(view.position[r]),
                            glm::dvec3(view.direction[r]),
                            view.weight[r],
                            view.path_mm[r],
                            view.bounces[r],
                            view.facet[r]};
        // The first ray of a hit pixel is the reflection off the entry facet.
        if (r == first) {
            list.reflected = ray;
        } else {
            list.exits.push_back(ray);
        }
    }
    return list;
}

}  // namespace gem
