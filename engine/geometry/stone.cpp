#include "geometry/stone.hpp"

#include <algorithm>
#include <cmath>

namespace gem {

const char* to_string(FacetKind kind) {
    switch (kind) {
        case FacetKind::table:
            return "table";
        case FacetKind::crown:
            return "crown";
        case FacetKind::girdle:
            return "girdle";
        case FacetKind::pavilion:
            return "pavilion";
        case FacetKind::culet:
            return "culet";
        case FacetKind::other:
            return "other";
    }
    return "other";
}

double bounding_radius(const std::vector<glm::dvec3>& vertices) {
    double r2 = 0.0;
    for (const glm::dvec3& v : vertices) r2 = std::max(r2, glm::dot(v, v));
    return std::sqrt(r2);
}

}  // namespace gem
