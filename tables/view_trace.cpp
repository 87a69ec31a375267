#include "view_trace.hpp"

#include <algorithm>

#include "picture/camera.hpp"

namespace gem::tables {

namespace {

// Step in n for the derivative: small against diamond's 0.044 spread over the visible range
// (so the path stays the same), large enough that double rounding is far below it.
constexpr double kIndexStep = 1e-4;

// Index in `candidates` of the first exit after `from` that left by the same facet after as
// many bounces, or -1.
int same_path(const std::vector<TracedRay>& candidates, std::size_t from, const TracedRay& ray) {
    for (std::size_t i = from; i < candidates.size(); ++i) {
        if (candidates[i].facet == ray.facet && candidates[i].bounces == ray.bounces) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

}  // namespace

CameraModel table_camera(const Stone& stone) {
    CameraModel camera;
    camera.kind = CameraModel::Kind::orthographic;
    camera.field_mm = 2.0 * bounding_radius(stone.vertices) * 1.05;
    return camera;
}

TraceSettings table_trace_settings(const BuildParams& params) {
    TraceSettings settings;
    settings.max_depth = static_cast<int>(params.max_depth);
    settings.min_weight = params.weight_threshold;
    return settings;
}

ViewTracer::ViewTracer(const Stone& stone, const CameraModel& camera, const ViewGrid& grid,
                       const BuildParams& params)
    : camera_(camera),
      grid_(grid),
      params_(params),
      tracer_(stone),
      settings_(table_trace_settings(params)),
      ior_(stone.material.index(kFraunhoferD)) {}

Ray ViewTracer::pixel_ray(std::uint32_t view, std::uint32_t side, std::uint32_t column,
                          std::uint32_t row) const {
    return camera_ray(camera_, grid_.basis(view),
                      pixel_centre(column, row, side, camera_.field_mm));
}

void ViewTracer::trace_pixel(std::uint32_t view, std::uint32_t side, std::uint32_t column,
                             std::uint32_t row, RayList& out) const {
    tracer_.trace(pixel_ray(view, side, column, row), ior_, settings_, out);
}

std::vector<RayList> ViewTracer::trace_view(std::uint32_t view, std::uint32_t level) const {
    const std::uint32_t side = params_.levels[level];
    std::vector<RayList> lists(static_cast<std::size_t>(side) * side);
    for (std::uint32_t row = 0; row < side; ++row) {
        for (std::uint32_t column = 0; column < side; ++column) {
            trace_pixel(view, side, column, row,
                        lists[static_cast<std::size_t>(row) * side + column]);
        }
    }
    return lists;
}

std::vector<glm::dvec3> ViewTracer::derivatives(std::uint32_t view, std::uint32_t level,
                                                const std::vector<RayList>& lists) const {
    const std::uint32_t side = params_.levels[level];
    std::vector<glm::dvec3> out;
    RayList plus;
    RayList minus;
    for (std::size_t p = 0; p < lists.size(); ++p) {
        if (!lists[p].hit) continue;
        const auto column = static_cast<std::uint32_t>(p % side);
        const auto row = static_cast<std::uint32_t>(p / side);
        const Ray ray = pixel_ray(view, side, column, row);
        tracer_.trace(ray, ior_ + kIndexStep, settings_, plus);
        tracer_.trace(ray, ior_ - kIndexStep, settings_, minus);
        std::size_t next_plus = 0;
        std::size_t next_minus = 0;
        for (const TracedRay& exit : lists[p].exits) {
            const int a = same_path(plus.exits, next_plus, exit);
            const int b = same_path(minus.exits, next_minus, exit);
            if (a >= 0) next_plus = static_cast<std::size_t>(a) + 1;
            if (b >= 0) next_minus = static_cast<std::size_t>(b) + 1;
            if (a >= 0 && b >= 0) {
                out.push_back((plus.exits[a].direction - minus.exits[b].direction) /
                              (2.0 * kIndexStep));
            } else if (a >= 0) {
                out.push_back((plus.exits[a].direction - exit.direction) / kIndexStep);
            } else if (b >= 0) {
                out.push_back((exit.direction - minus.exits[b].direction) / kIndexStep);
            } else {
                out.push_back(glm::dvec3(0.0));
            }
        }
    }
    return out;
}

}  // namespace gem::tables
