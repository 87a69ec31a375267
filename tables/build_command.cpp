// gemtables build: traces every stored view of a stone at every level and writes the database.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <thread>

#include "commands.hpp"
#include "progress.hpp"
#include "stone_file.hpp"
#include "table_build.hpp"
#include "tables/view_grid.hpp"
#include "trace/parallel.hpp"

namespace gem::tables {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

std::string megabytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f MB", static_cast<double>(bytes) / 1e6);
    return text;
}

}  // namespace

int run_build(const BuildOptions& o) {
    Result<Stone> loaded = load_stone_file(o.stone_file);
    if (!loaded) return fail(loaded.error());
    const Stone& stone = loaded.value();

    BuildParams params;
    params.levels = o.levels;
    params.grid.spacing_rad = o.spacing_deg * kDegree;
    params.grid.min_elevation_rad = o.min_elevation_deg * kDegree;
    params.max_depth = o.depth;
    params.weight_threshold = o.threshold;
    params.dispersion = o.dispersion;
    Result<ViewGrid> grid = ViewGrid::build(params.grid, stone.symmetry);
    if (!grid) return fail("--spacing/--min-elevation: " + grid.error());

    const auto views = static_cast<std::uint32_t>(grid.value().size());
    std::uint64_t pixels_per_view = 0;
    for (std::uint32_t side : params.levels) pixels_per_view += std::uint64_t{side} * side;
    const unsigned jobs = o.jobs > 0 ? o.jobs : worker_count();
    std::printf(
        "gemtables: %s (%s, %zu facets, %zu symmetries), %u views × %zu levels, "
        "%u jobs\n",
        o.stone_file.c_str(), stone.material.name.c_str(), stone.facets.size(),
        stone.symmetry.size(), views, params.levels.size(), jobs);
    std::fflush(stdout);

    Progress progress(std::uint64_t{views} * params.levels.size(), Progress::stdout_is_terminal());
    const auto start = std::chrono::steady_clock::now();
    Result<WriteSummary> written =
        trace_and_write(o.out, stone, params, grid.value(), jobs, [&] { progress.advance(); });
    progress.finish();
    if (!written) return fail(written.error());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const WriteSummary& s = written.value();
    const std::uint64_t pixel_lists = pixels_per_view * views;
    std::printf(
        "gemtables: wrote %s: %u views, %s (%s raw), %llu hit pixels, %llu rays\n", o.out.c_str(),
        views, megabytes(s.file_bytes).c_str(), megabytes(s.raw_payload_bytes).c_str(),
        static_cast<unsigned long long>(s.hit_pixels), static_cast<unsigned long long>(s.rays));
    std::printf("gemtables: %.2f s, %.3g pixel ray-lists/s (%.3g per job)\n", seconds,
                pixel_lists / std::max(seconds, 1e-9),
                pixel_lists / std::max(seconds, 1e-9) / jobs);
    return 0;
}

}  // namespace gem::tables
