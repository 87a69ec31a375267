#include "database_cache.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <numbers>

#include "table_build.hpp"
#include "trace/parallel.hpp"

namespace gem::accuracy {

std::string describe(const TableConfig& c) {
    char text[96];
    std::snprintf(text, sizeof text, "L%u_S%g_D%d_T%g%s", c.level, c.spacing_deg, c.depth,
                  c.threshold, c.dispersion ? "_disp" : "");
    return text;
}

Result<CachedDatabase> DatabaseCache::get(const std::string& stone_name, const Stone& stone,
                                          const TableConfig& config, double min_elevation_deg) {
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec);
    if (ec) return Error{"cannot create " + folder_.string() + ": " + ec.message()};
    const std::string key =
        stone_name + "_" + describe(config) + "_E" + std::to_string(int(min_elevation_deg));
    const std::filesystem::path path = folder_ / (key + ".gemdb");
    const std::filesystem::path timing = folder_ / (key + ".build_s");

    CachedDatabase out;
    {
        std::ifstream in(timing);
        out.from_cache = std::filesystem::exists(path) && (in >> out.build_s);
    }
    if (!out.from_cache) {
        BuildParams params;
        params.levels = {config.level};
        params.grid.spacing_rad = config.spacing_deg * std::numbers::pi / 180.0;
        params.grid.min_elevation_rad = min_elevation_deg * std::numbers::pi / 180.0;
        params.max_depth = static_cast<std::uint32_t>(config.depth);
        params.weight_threshold = config.threshold;
        params.dispersion = config.dispersion;
        auto grid = ViewGrid::build(params.grid, stone.symmetry);
        if (!grid) return Error{grid.error()};
        const auto start = std::chrono::steady_clock::now();
        auto written = tables::trace_and_write(path, stone, params, grid.value(), worker_count());
        if (!written) return Error{written.error()};
        out.build_s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::ofstream(timing) << out.build_s << "\n";
        std::printf("  built %s: %zu views, %.1f MB in %.1f s\n", key.c_str(), grid.value().size(),
                    double(written.value().file_bytes) / 1e6, out.build_s);
        std::fflush(stdout);
    }
    auto db = Database::open(path);
    if (!db) return Error{db.error()};
    out.database = std::make_shared<const Database>(std::move(db).value());
    out.bytes = std::filesystem::file_size(path, ec);
    return out;
}

}  // namespace gem::accuracy
