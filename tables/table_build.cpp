#include "table_build.hpp"

#include "view_trace.hpp"

namespace gem::tables {

Result<WriteSummary> trace_and_write(const std::filesystem::path& path, const Stone& stone,
                                     const BuildParams& params, const ViewGrid& grid,
                                     unsigned threads, const std::function<void()>& on_table) {
    const CameraModel camera = table_camera(stone);
    const ViewTracer tracer(stone, camera, grid, params);
    auto done = [&] {
        if (on_table) on_table();
    };
    TraceViewFn trace = [&](std::uint32_t view, std::uint32_t level) {
        std::vector<RayList> lists = tracer.trace_view(view, level);
        // With dispersion the derivative pass follows; the table counts as done after it.
        if (!params.dispersion) done();
        return lists;
    };
    TraceDerivativesFn derivatives = [&](std::uint32_t view, std::uint32_t level,
                                         const std::vector<RayList>& lists) {
        std::vector<glm::dvec3> d = tracer.derivatives(view, level, lists);
        done();
        return d;
    };
    WriteOptions options;
    options.threads = threads;
    return write_database(path, stone, camera, params, grid, trace,
                          params.dispersion ? derivatives : TraceDerivativesFn{}, options);
}

}  // namespace gem::tables
