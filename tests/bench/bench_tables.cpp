// Figures of the pre-computation stage and the streaming cache, printed (not asserted):
// build throughput per core, the default diamond database's build time and sizes, decode
// times, what one cache worker sustains, cold request-to-resident time, and the largest
// quantisation errors against the exact tracer.
//
//   bench_tables [--estimate] [--keep PATH]
// --estimate times a sample of views and extrapolates the full build instead of running it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "commands.hpp"
#include "gemdb/reader.hpp"
#include "gemdb/view_cache.hpp"
#include "scene/stone_file.hpp"
#include "trace/parallel.hpp"
#include "view_trace.hpp"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Single-thread tracing speed of the default diamond, and the full build's size in pixels.
void build_throughput(const gem::Stone& stone, const gem::tables::BuildOptions& defaults,
                      bool estimate) {
    gem::BuildParams params;
    params.levels = defaults.levels;
    params.grid.spacing_rad = defaults.spacing_deg * std::numbers::pi / 180.0;
    params.grid.min_elevation_rad = defaults.min_elevation_deg * std::numbers::pi / 180.0;
    const gem::ViewGrid grid = gem::ViewGrid::build(params.grid, stone.symmetry).value();
    const gem::CameraModel camera = gem::tables::table_camera(stone);
    const gem::tables::ViewTracer tracer(stone, camera, grid, params);
    const std::uint32_t sample_views = std::min<std::uint32_t>(4, grid.size());
    const auto start = Clock::now();
    std::uint64_t pixels = 0;
    for (std::uint32_t v = 0; v < sample_views; ++v) {
        pixels += tracer.trace_view(v * (grid.size() / sample_views), 0).size();
    }
    const double per_core = pixels / seconds_since(start);
    std::uint64_t per_view = 0;
    for (std::uint32_t side : params.levels) per_view += std::uint64_t{side} * side;
    const double total = static_cast<double>(per_view) * grid.size();
    std::printf(
        "build throughput     %.3g pixel ray-lists/s per core (one thread, %u views at "
        "%u px)\n",
        per_core, sample_views, params.levels[0]);
    std::printf("default database     %zu views × %zu levels = %.3g pixel ray-lists\n", grid.size(),
                params.levels.size(), total);
    if (estimate) {
        std::printf("default build time   ~%.0f s estimated on %u cores (perfect scaling)\n",
                    total / per_core / gem::worker_count(), gem::worker_count());
    }
}

void decode_times(const gem::Database& db) {
    for (std::uint32_t l = 0; l < db.level_count(); ++l) {
        const std::uint32_t n = std::min<std::uint32_t>(db.view_count(), 16);
        const auto start = Clock::now();
        for (std::uint32_t v = 0; v < n; ++v) {
            if (!db.decode(v, l)) std::printf("decode failed: view %u level %u\n", v, l);
        }
        std::printf("decode %4u px       %.3f ms per view (mean of %u)\n", db.params().levels[l],
                    seconds_since(start) / n * 1e3, n);
    }
}

void cache_figures(const std::shared_ptr<const gem::Database>& db) {
    const std::uint32_t finest = db->level_count() - 1;
    auto source = std::make_shared<gem::DatabaseViewSource>(db);
    {
        gem::ViewCacheOptions options;
        options.memory_bytes = std::size_t{1} << 34;
        options.max_demand_requests = db->view_count() * db->level_count();
        gem::ViewCache cache(source, options);
        const auto start = Clock::now();
        // Each request queues its view's coarse level and the finest one.
        for (std::uint32_t v = 0; v < db->view_count(); ++v) {
            (void)cache.acquire(db->grid().direction(v), finest);
        }
        (void)cache.wait_idle(std::chrono::minutes(10));
        const double took = seconds_since(start);
        const gem::ViewCacheStats s = cache.stats();
        std::printf(
            "one cache worker     %.1f decodes/s sustained (%llu decodes of coarse + "
            "finest level, %.1f MB resident)\n",
            s.decodes / took, static_cast<unsigned long long>(s.decodes), s.bytes_resident / 1e6);
    }
    std::vector<double> cold;
    for (std::uint32_t v = 0; v < std::min<std::uint32_t>(db->view_count(), 9); ++v) {
        gem::ViewCache cache(source);
        const auto start = Clock::now();
        (void)cache.acquire(db->grid().direction(v), finest);
        while (!cache.resident(v, finest) && !cache.bad(v, finest) && seconds_since(start) < 60) {
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
        cold.push_back(seconds_since(start));
    }
    std::sort(cold.begin(), cold.end());
    std::printf(
        "cold view            %.2f ms request → resident at %u px (median of %zu; the "
        "coarse level decodes first)\n",
        cold[cold.size() / 2] * 1e3, db->params().levels[finest], cold.size());
}

}  // namespace

int main(int argc, char** argv) {
    bool estimate = false;
    std::string keep;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--estimate") == 0) estimate = true;
        if (std::strcmp(argv[i], "--keep") == 0 && i + 1 < argc) keep = argv[++i];
    }
    gem::tables::BuildOptions build;  // the defaults of `gemtables build`
    build.stone_file = std::string(GEM_STONES_DIR) + "/tolkowsky-diamond.toml";
    build.out =
        keep.empty() ? (fs::temp_directory_path() / "bench_tables_diamond.gemdb").string() : keep;
    auto stone = gem::load_stone_file(build.stone_file);
    if (!stone) {
        std::fprintf(stderr, "%s\n", stone.error().c_str());
        return 1;
    }
    std::printf("== gemtables on %s, %u cores\n", build.stone_file.c_str(), gem::worker_count());
    build_throughput(stone.value(), build, estimate);
    if (estimate) {
        // A coarser database stands in for the sizes and cache figures.
        build.levels = {64, 128};
        build.spacing_deg = 10.0;
        std::printf("(--estimate: sizes below are for levels 64,128 at 10° spacing)\n");
    }
    const auto start = Clock::now();
    if (gem::tables::run_build(build) != 0) return 1;
    std::printf("build time           %.1f s\n", seconds_since(start));
    if (gem::tables::run_info(build.out) != 0) return 1;
    auto opened = gem::Database::open(build.out);
    if (!opened) return 1;
    auto db = std::make_shared<const gem::Database>(std::move(opened).value());
    decode_times(*db);
    cache_figures(db);
    gem::tables::VerifyOptions verify;
    verify.database = build.out;
    verify.samples = 20000;
    const int verified = gem::tables::run_verify(verify);
    if (keep.empty()) fs::remove(build.out);
    return verified;
}
