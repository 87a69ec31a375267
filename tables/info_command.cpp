// gemtables info: what a database holds and what its bytes go to.
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <vector>

#include "commands.hpp"
#include "gemdb/reader.hpp"

namespace gem::tables {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

struct LevelTotals {
    std::uint64_t compressed = 0;
    std::uint64_t raw = 0;
    std::uint64_t hits = 0;
    std::uint64_t rays = 0;
};

void print_totals(const char* name, const LevelTotals& t, std::uint32_t views) {
    const double ratio = t.compressed > 0 ? static_cast<double>(t.raw) / t.compressed : 0.0;
    const double per_pixel = t.hits > 0 ? static_cast<double>(t.compressed) / t.hits : 0.0;
    const double rays_per_hit = t.hits > 0 ? static_cast<double>(t.rays) / t.hits : 0.0;
    std::printf(
        "  %-10s %12llu bytes (%8.1f per view), raw %12llu, ratio %5.2f, "
        "%5.2f bytes/stored pixel, %.2f rays/hit pixel\n",
        name, static_cast<unsigned long long>(t.compressed),
        static_cast<double>(t.compressed) / views, static_cast<unsigned long long>(t.raw), ratio,
        per_pixel, rays_per_hit);
}

}  // namespace

int run_info(const std::string& path) {
    Result<Database> opened = Database::open(path);
    if (!opened) return fail(opened.error());
    const Database& db = opened.value();
    const Stone& stone = db.stone();
    const BuildParams& p = db.params();
    const CameraModel& camera = db.camera();

    std::printf("%s\n", path.c_str());
    std::error_code ec;
    std::printf("format       1.%u, %llu bytes\n", db.version_minor(),
                static_cast<unsigned long long>(std::filesystem::file_size(path, ec)));
    std::printf("stone        %s: %zu facets, %zu vertices, %zu triangles, %s, %zu symmetries\n",
                stone.name.c_str(), stone.facets.size(), stone.vertices.size(),
                stone.triangles.size(), stone.convex ? "convex" : "non-convex",
                stone.symmetry.size());
    std::printf("material     %s, n(D) = %.4f, dispersion n(G)-n(B) = %.4f\n",
                db.material().name.c_str(), db.material().index(kFraunhoferD),
                db.material().index(kFraunhoferG) - db.material().index(kFraunhoferB));
    if (camera.kind == CameraModel::Kind::perspective) {
        std::printf("camera       perspective at %.2f mm, field %.3f mm\n", camera.distance_mm,
                    camera.field_mm);
    } else {
        std::printf("camera       orthographic, field %.3f mm\n", camera.field_mm);
    }
    std::printf("params       levels");
    for (std::uint32_t side : p.levels) std::printf(" %u", side);
    std::printf(", spacing %.3f°, min elevation %.2f°, depth %u, threshold %g, dispersion %s\n",
                p.grid.spacing_rad / kDegree, p.grid.min_elevation_rad / kDegree, p.max_depth,
                p.weight_threshold, p.dispersion ? "yes" : "no");
    std::printf(
        "views        %u stored (%u on the whole sphere, folded by %zu of the "
        "stone's symmetries)\n",
        db.view_count(), db.grid().sphere_count(), db.grid().group().size());

    std::vector<LevelTotals> levels(db.level_count());
    LevelTotals all;
    for (std::uint32_t v = 0; v < db.view_count(); ++v) {
        for (std::uint32_t l = 0; l < db.level_count(); ++l) {
            const PayloadInfo& info = db.payload(v, l);
            for (LevelTotals* t : {&levels[l], &all}) {
                t->compressed += info.compressed_bytes;
                t->raw += info.raw_bytes;
                t->hits += info.hit_pixels;
                t->rays += info.rays;
            }
        }
    }
    std::printf("payloads\n");
    for (std::uint32_t l = 0; l < db.level_count(); ++l) {
        char name[32];
        std::snprintf(name, sizeof name, "%u px", p.levels[l]);
        print_totals(name, levels[l], db.view_count());
    }
    print_totals("all", all, db.view_count());
    return 0;
}

}  // namespace gem::tables
