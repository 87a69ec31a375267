// Figures of the GPU shading stage, printed (not asserted): milliseconds per frame of every
// method on this machine's GL (llvmpipe without a GPU) at 1280×720 and 1920×1080 with the
// stone filling about half the screen height, at depth 4 and 8, loose and in a ring; for the
// table method, the share of each frame spent streaming views (cache lookups, texture
// uploads). Frames are a turntable (azimuth steps of 3° at 35° elevation), each bounded by
// glFinish.
//
//   bench_gpu [--frames N] [--quick]
// --quick: 1280×720 only, fewer frames (a smoke run).
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/cuts.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/render_target.hpp"
#include "gpu/ring_mesh.hpp"
#include "optics/material.hpp"
#include "table_build.hpp"
#include "trace/parallel.hpp"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

// A database of the Tolkowsky diamond at `depth`: levels 256 and 512, views every 8° above
// −10° elevation (what a turntable at 35° needs).
std::shared_ptr<const gem::Database> build_database(const gem::Stone& stone, int depth) {
    gem::BuildParams params;
    params.levels = {256, 512};
    params.grid.spacing_rad = 8.0 * std::numbers::pi / 180.0;
    params.grid.min_elevation_rad = -10.0 * std::numbers::pi / 180.0;
    params.max_depth = static_cast<std::uint32_t>(depth);
    auto grid = gem::ViewGrid::build(params.grid, stone.symmetry);
    const fs::path path =
        fs::temp_directory_path() / ("bench_gpu_depth" + std::to_string(depth) + ".gemdb");
    const auto start = Clock::now();
    auto written =
        gem::tables::trace_and_write(path, stone, params, grid.value(), gem::worker_count());
    if (!written) {
        std::fprintf(stderr, "bench_gpu: %s\n", written.error().c_str());
        std::exit(1);
    }
    std::printf("built %s: %zu views, %.1f MB in %.1f s\n", path.c_str(), grid.value().size(),
                written.value().file_bytes / 1e6,
                std::chrono::duration<double>(Clock::now() - start).count());
    auto db = gem::Database::open(path);
    return std::make_shared<const gem::Database>(std::move(db).value());
}

struct Case {
    gem::gpu::Method method;
    bool blend = false;
    int depth = 8;
    bool ring = false;
};

void run(const Case& c, const gem::Stone& stone, std::shared_ptr<const gem::Database> db,
         const gem::Environment& environment, const gem::gpu::RingMesh& ring, int width, int height,
         int frames) {
    gem::gpu::FrameSetup setup;
    setup.method = c.method;
    setup.database = std::move(db);
    setup.stone = stone;
    setup.material = stone.material;
    setup.shading.lights = {{{20.0, 60.0, 40.0}, false, {2.0, 2.0, 2.0}},
                            {{-30.0, 50.0, -20.0}, false, {1.5, 1.5, 1.5}}};
    setup.trace.max_depth = c.depth;
    setup.table.blend = c.blend;
    setup.environment = &environment;
    if (c.ring) setup.ring = &ring;
    auto renderer = gem::gpu::FrameRenderer::make(std::move(setup));
    if (!renderer) {
        std::fprintf(stderr, "bench_gpu: %s\n", renderer.error().c_str());
        std::exit(1);
    }
    auto target = gem::gpu::RenderTarget::make(width, height);
    target.value().bind();
    double total = 0.0;
    double streaming = 0.0;
    double worst = 0.0;
    int stand_ins = 0;
    for (int f = -1; f < frames; ++f) {  // frame −1 warms up (program, first views)
        gem::CameraSettings cs;
        cs.elevation_deg = 35.0;
        cs.azimuth_deg = 3.0 * f;
        cs.zoom = 0.5;  // the stone's bounding sphere spans half the image height
        auto camera = gem::Camera::make(cs, renderer.value().stone_radius_mm(), width, height);
        if (auto* table = renderer.value().table()) {
            const double omega = 3.0 * std::numbers::pi / 180.0 * 60.0;
            table->cache().prefetch(-camera.value().forward(), {0.0, omega, 0.0},
                                    table->level_for(table->database().camera().field_mm /
                                                     camera.value().pixel_size()));
            if (f < 0) table->cache().wait_idle(std::chrono::seconds(60));
        }
        auto stats = renderer.value().render(camera.value(), true);
        if (!stats) {
            std::fprintf(stderr, "bench_gpu: %s\n", stats.error().c_str());
            std::exit(1);
        }
        if (f < 0) continue;
        const auto& t = stats.value().table;
        total += stats.value().cpu_ms;
        streaming += t.acquire_ms + t.upload_ms;
        worst = std::max(worst, stats.value().cpu_ms);
        stand_ins += (renderer.value().table() != nullptr && !t.exact) ? 1 : 0;
    }
    std::printf("%-6s %-7s depth %d %-5s %4d×%-4d  %8.1f ms/frame (worst %7.1f)  %5.2f fps",
                gem::gpu::to_string(c.method),
                c.method == gem::gpu::Method::table ? (c.blend ? "blend" : "nearest") : "", c.depth,
                c.ring ? "ring" : "loose", width, height, total / frames, worst,
                1000.0 * frames / total);
    if (c.method == gem::gpu::Method::table) {
        std::printf("  streaming %4.1f%%  stand-in frames %d/%d", 100.0 * streaming / total,
                    stand_ins, frames);
    }
    std::printf("\n");
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 8;
    bool quick = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) frames = std::atoi(argv[++i]);
        if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    }
    if (quick) frames = std::min(frames, 3);
    auto context = gem::gpu::EglContext::headless();
    if (!context) {
        std::fprintf(stderr, "bench_gpu: %s\n", context.error().c_str());
        return 1;
    }
    std::printf("GL: %s\n", context.value().description().c_str());
    auto stone = gem::make_cut(gem::default_cut_params(gem::CutShape::round_brilliant),
                               *gem::find_material("diamond"));
    const gem::Environment environment = gem::Environment::studio();
    auto ring = gem::gpu::make_ring({}, stone.value());
    std::shared_ptr<const gem::Database> db[2] = {build_database(stone.value(), 4),
                                                  build_database(stone.value(), 8)};
    std::vector<std::pair<int, int>> sizes = {{1280, 720}, {1920, 1080}};
    if (quick) sizes.resize(1);
    for (const auto& [w, h] : sizes) {
        for (int d = 0; d < 2; ++d) {
            const int depth = d == 0 ? 4 : 8;
            for (bool ring_on : {false, true}) {
                run({gem::gpu::Method::table, false, depth, ring_on}, stone.value(), db[d],
                    environment, ring.value(), w, h, frames);
                run({gem::gpu::Method::table, true, depth, ring_on}, stone.value(), db[d],
                    environment, ring.value(), w, h, frames);
                run({gem::gpu::Method::trace, false, depth, ring_on}, stone.value(), nullptr,
                    environment, ring.value(), w, h, frames);
            }
        }
        for (bool ring_on : {false, true}) {
            run({gem::gpu::Method::phong, false, 0, ring_on}, stone.value(), nullptr, environment,
                ring.value(), w, h, frames);
        }
    }
    return 0;
}
