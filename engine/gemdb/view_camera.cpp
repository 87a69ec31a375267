#include "gemdb/database_types.hpp"

namespace gem {

glm::dvec2 pixel_centre(std::uint32_t column, std::uint32_t row, std::uint32_t side,
                        double field_mm) {
    return {((column + 0.5) / side - 0.5) * field_mm, (0.5 - (row + 0.5) / side) * field_mm};
}

Ray camera_ray(const CameraModel& camera, const CameraBasis& basis, const glm::dvec2& xy) {
    const glm::dvec3 on_plane = xy.x * basis.right + xy.y * basis.up;
    if (camera.kind == CameraModel::Kind::perspective) {
        const glm::dvec3 eye = camera.distance_mm * basis.view;
        return {eye, glm::normalize(on_plane - eye)};
    }
    return {on_plane + camera.field_mm * basis.view, -basis.view};
}

}  // namespace gem
