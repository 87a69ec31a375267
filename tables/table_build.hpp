#pragma once
// Traces every stored view of a stone and writes its database: the one place that joins the
// exact tracer (view_trace.hpp) to the writer, for `gemtables build`, the benchmarks and the
// tests that need a real database.

#include <filesystem>
#include <functional>

#include "gemdb/writer.hpp"
#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem::tables {

// `grid` must be built from params.grid and stone.symmetry; the camera is table_camera(stone).
// With params.dispersion the derivative pass runs too. `on_table` is called once per finished
// table (view × level), from the tracing threads.
Result<WriteSummary> trace_and_write(const std::filesystem::path& path, const Stone& stone,
                                     const BuildParams& params, const ViewGrid& grid,
                                     unsigned threads, const std::function<void()>& on_table = {});

}  // namespace gem::tables
