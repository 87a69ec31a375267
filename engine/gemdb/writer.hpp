#pragma once
// Writes a .gemdb database (docs/gemdb-format.md): the stone, camera, build parameters and
// view grid, then every view at every level as its own zstd-compressed payload with an index
// of offsets, sizes and xxHash64 checksums. The write is atomic and the bytes depend only on
// the inputs, also when views are traced on several threads.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "gemdb/database_types.hpp"
#include "gemdb/view_grid.hpp"
#include "geometry/stone.hpp"
#include "trace/ray_list.hpp"
#include "util/result.hpp"

namespace gem {

// Ray-lists of stored view `view` at level `level`: side² of them, row-major, row 0 at the
// top, traced with the view's canonical basis (ViewGrid::basis) through pixel_centre().
using TraceViewFn = std::function<std::vector<RayList>(std::uint32_t view, std::uint32_t level)>;
// With BuildParams::dispersion: d(direction)/dn of every exit ray in `lists` (hit pixels in
// order, exits in order, before light rays are dropped).
using TraceDerivativesFn = std::function<std::vector<glm::dvec3>(
    std::uint32_t view, std::uint32_t level, const std::vector<RayList>& lists)>;

struct WriteOptions {
    unsigned threads = 1;  // >1 calls the callbacks from several threads at once
    int zstd_level = 9;
};

struct WriteSummary {
    std::uint64_t file_bytes = 0;
    std::uint64_t raw_payload_bytes = 0;
    std::uint64_t rays = 0;
    std::uint64_t hit_pixels = 0;
};

// `grid` must be built from params.grid and stone.symmetry. Errors name the file.
Result<WriteSummary> write_database(const std::filesystem::path& path, const Stone& stone,
                                    const CameraModel& camera, const BuildParams& params,
                                    const ViewGrid& grid, const TraceViewFn& trace_view,
                                    const TraceDerivativesFn& trace_derivatives = {},
                                    const WriteOptions& options = {});

}  // namespace gem
