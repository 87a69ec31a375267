#pragma once
// Traces the stored views of a database with the exact tracer: the one definition of how a
// view's pixels map to rays and tracer settings, shared by `build` and `verify` so that a
// re-trace reproduces exactly what was stored.

#include <cstdint>
#include <vector>

#include "gemdb/database_types.hpp"
#include "geometry/stone.hpp"
#include "trace/tracer.hpp"

namespace gem::tables {

// An orthographic window a little wider than the stone's bounding sphere, so every view
// frames the whole stone.
CameraModel table_camera(const Stone& stone);

// The tracer settings a database's parameters stand for. A branch lighter than the storage
// threshold can only produce exits lighter still, which the writer drops anyway.
TraceSettings table_trace_settings(const BuildParams& params);

class ViewTracer {
  public:
    // Keeps references: stone, camera, grid and params must outlive it. Traces at n(D).
    ViewTracer(const Stone& stone, const CameraModel& camera, const ViewGrid& grid,
               const BuildParams& params);

    void trace_pixel(std::uint32_t view, std::uint32_t side, std::uint32_t column,
                     std::uint32_t row, RayList& out) const;
    std::vector<RayList> trace_view(std::uint32_t view, std::uint32_t level) const;
    // d(direction)/dn of every exit ray of `lists` (hit pixels in order), by central
    // differences in n; an exit whose path changes with n (a ray tree that splits
    // differently) gets a one-sided difference, or zero when it exists only at n.
    std::vector<glm::dvec3> derivatives(std::uint32_t view, std::uint32_t level,
                                        const std::vector<RayList>& lists) const;

  private:
    Ray pixel_ray(std::uint32_t view, std::uint32_t side, std::uint32_t column,
                  std::uint32_t row) const;

    const CameraModel& camera_;
    const ViewGrid& grid_;
    const BuildParams& params_;
    Tracer tracer_;
    TraceSettings settings_;
    double ior_ = 1.5;
};

}  // namespace gem::tables
