// gemtables build: traces every stored view of a stone at every level and writes the database.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <thread>

#include "budget.hpp"
#include "commands.hpp"
#include "gemdb/view_grid.hpp"
#include "piece/stone_shape.hpp"
#include "process_limits.hpp"
#include "progress.hpp"
#include "scene/stone_file.hpp"
#include "table_build.hpp"
#include "trace/parallel.hpp"

namespace gem::tables {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

std::string megabytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f MB", static_cast<double>(bytes) / 1e6);
    return text;
}

// Prints each pilot measurement and the choice; the parameters to build with.
Result<BuildParams> choose_under_budget(const Stone& stone, const BuildOptions& o) {
    if (o.screen_px <= 0) return Error{"--budget needs --screen (pixels across the stone)"};
    BudgetRequest request;
    request.budget_delta_e = o.budget_delta_e;
    request.screen_px = o.screen_px;
    request.min_elevation_deg = o.min_elevation_deg;
    request.max_jump_px = o.max_jump_px;
    std::printf(
        "gemtables: choosing parameters for mean ΔE00 ≤ %g at %d px across, views jumping ≤ "
        "%g px\n",
        o.budget_delta_e, o.screen_px, o.max_jump_px);
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    Result<BudgetChoice> choice = choose_parameters(stone, request, [](const BudgetStep& s) {
        std::printf("gemtables:   %-10s %-14s ΔE00 %6.2f  %s\n", s.parameter.c_str(),
                    s.value.c_str(), s.delta_e, s.accepted ? "within budget" : "over");
        std::fflush(stdout);
    });
    if (!choice) return Error{choice.error()};
    const BudgetChoice& c = choice.value();
    if (!c.met)
        std::printf(
            "gemtables: warning: even the most accurate candidate is over the budget (ΔE00 "
            "%.2f); building it\n",
            c.delta_e);
    if (!c.jump_met)
        std::printf("gemtables: warning: even %g° between views jumps more than %g px\n",
                    c.spacing_deg, o.max_jump_px);
    std::printf(
        "gemtables: chose spacing %g° (jump %.1f px at the rim), levels %u/%u, depth %u, "
        "threshold %g, dispersion %s: ΔE00 %.2f at a stored view, %.2f at the median %.2f° "
        "from one (%.1f s of pilot renders)\n",
        c.spacing_deg, c.spacing_deg * kDegree * o.screen_px / 2.0, c.params.levels.front(),
        c.params.levels.back(), c.params.max_depth, c.params.weight_threshold,
        c.params.dispersion ? "on" : "off", c.delta_e, c.between_delta_e, c.offset_deg,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return c.params;
}

}  // namespace

int run_build(const BuildOptions& o) {
    if (o.idle) {
        std::printf("gemtables: %s\n", run_at_idle_priority().c_str());
        std::fflush(stdout);
    }
    if (o.memory_mb > 0) {
        auto limited = limit_memory(o.memory_mb);
        if (!limited) return fail(limited.error());
        if (!limited.value().empty()) std::printf("gemtables: %s\n", limited.value().c_str());
    }
    Result<Stone> loaded = load_stone_file(o.stone_file);
    if (!loaded) return fail(loaded.error());
    if (o.width_mm > 0.0) loaded = stone_at_width(std::move(loaded).value(), o.width_mm);
    const Stone& stone = loaded.value();

    BuildParams params;
    params.levels = o.levels;
    params.grid.spacing_rad = o.spacing_deg * kDegree;
    params.grid.min_elevation_rad = o.min_elevation_deg * kDegree;
    params.max_depth = o.depth;
    params.weight_threshold = o.threshold;
    params.dispersion = o.dispersion;
    if (o.budget_delta_e > 0.0) {
        Result<BuildParams> chosen = choose_under_budget(stone, o);
        if (!chosen) return fail(chosen.error());
        params = chosen.value();
        if (o.choose_only) return 0;
    }
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
