#pragma once
// What a .gemdb records besides the stone and the views: the camera model, the build
// parameters and the decoded form of one view (docs/gemdb-format.md).

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gemdb/quantise.hpp"
#include "gemdb/view_grid.hpp"
#include "trace/ray_list.hpp"

namespace gem {

struct CameraModel {
    enum class Kind : std::uint8_t { orthographic = 0, perspective = 1 };
    Kind kind = Kind::orthographic;
    double distance_mm = 0.0;  // perspective: camera distance from the stone's centre
    double field_mm = 10.0;    // side of the square image window through the stone's centre
};

struct BuildParams {
    std::vector<std::uint32_t> levels{64, 128, 256};  // image side in pixels, ascending
    ViewGridSpec grid;
    std::uint32_t max_depth = 12;    // tracer depth the tables were built with (recorded)
    double weight_threshold = 1e-4;  // exit rays lighter than this are dropped
    bool dispersion = false;         // store d(direction)/dn per ray
};

// Image point (mm from the centre, x right, y up) of pixel (column, row), row 0 at the top.
glm::dvec2 pixel_centre(std::uint32_t column, std::uint32_t row, std::uint32_t side,
                        double field_mm);
// The pixel ray through image point `xy` of a camera with basis `basis`; orthographic rays
// start `field_mm` in front of the centre, which is outside any stone the field frames.
Ray camera_ray(const CameraModel& camera, const CameraBasis& basis, const glm::dvec2& xy);

// One view at one level, flat for upload: pixel p owns rays [ray_offset[p], +ray_count[p]),
// the first reflection first, then the exit rays; a count of 0 is a miss.
struct DecodedView {
    std::uint32_t side = 0;
    std::vector<std::uint32_t> ray_offset;
    std::vector<std::uint16_t> ray_count;
    std::vector<float> truncated_weight;  // per pixel, including the weight of dropped rays
    std::vector<glm::vec3> direction;
    std::vector<float> weight;
    std::vector<float> path_mm;
    std::vector<glm::vec3> position;
    std::vector<std::uint16_t> bounces;
    std::vector<std::uint16_t> facet;
    std::vector<glm::vec3> dir_dn;  // empty unless the database stores dispersion
};

// Pixel `pixel` of a decoded view as a ray-list again (what the tracer gave, after
// quantisation), so the CPU shader can shade what a table holds.
RayList ray_list_at(const DecodedView& view, std::size_t pixel);

}  // namespace gem
