// Figures of the GPU shading stage, printed (not asserted): does a frame's cost follow the
// stone's pixels? Every method draws the round diamond at 1024×1024 with its bounding sphere
// at zoom 1, 0.62 (about a fifth of the picture), 0.5 and 0.25, and in its ring at the kiosk's
// start view (1920×1080, framed as the kiosk frames it: kiosk/stage/framing.hpp, the shipped
// stone_share 0.25); per view and method: the median
// ms per frame (each bounded by glFinish) over a turn of 1° a frame at 40° elevation and of
// its stone pass alone (between glFinish calls), the stone's pixels (counted on the CPU by the
// exact tracer's entry test), stone-pass ms per million stone pixels, and the frame's ratio to
// phong on the same view: the methods draw their frames in turn, so the ratio is the median of
// frame-by-frame ratios, each against the phong frame drawn just before (a busy machine slows
// both alike). The table method reads a database of the
// diamond at 256/1024 px every 10°, traced to the same depth. Last, the heart in ruby (not
// convex) beside phong: traced as its two convex pieces and through its triangles.
//
//   bench_gpu [--frames N] [--quick] [--only TEXT] [--methods TEXT]
// --quick: the 1024² views at zoom 1 and 0.25 only, 3 frames (a smoke run).
// --only: the views whose name contains TEXT (e.g. "zoom 0.62"), to repeat one comparison.
// --methods: the methods whose name contains TEXT (e.g. "trace depth"), and phong, the base.
// "by facet": the trace's stones shaded facet by facet, without the visibility pass.
#include <algorithm>
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
#include "optics/material.hpp"
#include "piece/ring_mesh.hpp"
#include "stage/framing.hpp"
#include "stage/start_view.hpp"
#include "table_build.hpp"
#include "trace/intersector.hpp"
#include "trace/parallel.hpp"

#include "bench_frame.hpp"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

using gem::gpu::TraceDispersion;

constexpr int kTraceDepth = 7;  // the depth the figures of the peer tracer were taken at
constexpr int kKioskDepth = 8;  // config/gemkiosk.toml: render.depth

std::shared_ptr<const gem::Database> build_database(const gem::Stone& stone, int depth) {
    gem::BuildParams params;
    params.levels = {256, 1024};
    params.grid.spacing_rad = 10.0 * std::numbers::pi / 180.0;
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

struct View {
    const char* name;
    int width, height;
    double zoom;
    double elevation_deg;
    bool ring;  // the kiosk's view: the ring too, framed from the start view and turned from it
};

constexpr double kStoneShare = 0.25;  // config/gemkiosk.toml: [picture] stone_share

struct Case {
    const char* name;
    std::string method;
    bool blend = false;
    int depth = kTraceDepth;
    TraceDispersion dispersion = TraceDispersion::none;
    bool triangles = false;  // a non-convex stone's triangles, not its convex pieces
    bool by_facet = false;   // without the visibility pass (FrameSetup::visibility_pass)
};

// The view of `frame` (a turn of 1° a frame), prepared for that turn and its tables' views
// waited for: decoding (the table's) is not shading.
gem::gpu::FrameView view_for(const View& v, const gem::gpu::FrameRenderer& r,
                             const gem::MetalMesh& ring, const gem::Stone& stone, int frame) {
    gem::gpu::FrameView out;
    out.omega = {0.0, 1.0 * std::numbers::pi / 180.0 * 30.0, 0.0};
    out.wait_for_views = true;
    if (v.ring) {
        const std::vector<glm::dvec3> points(ring.positions.begin(), ring.positions.end());
        const gem::kiosk::Framing framing =
            gem::kiosk::frame_ring(stone.vertices, points, gem::kiosk::kStartView,
                                   {v.width, v.height}, r.scene_radius_mm(), kStoneShare);
        gem::kiosk::ViewState view = gem::kiosk::kStartView;
        view.azimuth_deg += 1.0 * frame;
        out.camera = gem::kiosk::framed_camera(view, framing);
        // The kiosk frames the whole scene (the ring too).
        out.framing_mm = r.scene_radius_mm();
        return out;
    }
    out.camera.elevation_deg = v.elevation_deg;
    out.camera.azimuth_deg = 1.0 * frame;
    out.camera.zoom = v.zoom;
    out.framing_mm = r.stone_radius_mm();  // loose stones frame the stone
    return out;
}

gem::Camera camera_for(const View& v, const gem::gpu::FrameRenderer& r, const gem::MetalMesh& ring,
                       const gem::Stone& stone, int frame) {
    const gem::gpu::FrameView view = view_for(v, r, ring, stone, frame);
    return gem::Camera::make(view.camera, view.framing_mm, v.width, v.height).value();
}

// Pixels whose centre ray enters the stone, by the exact tracer's entry test.
long stone_pixels(const gem::Stone& stone, const gem::Camera& camera) {
    const auto surface = gem::make_intersector(stone);
    long hits = 0;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const gem::Ray ray = camera.ray(x + 0.5, y + 0.5);
            gem::SurfaceHit hit;
            hits += surface->next_entry(ray.origin, ray.direction, gem::kNoFacet, hit) ? 1 : 0;
        }
    }
    return hits;
}

// One method's renderer on one view, drawn in turn with the others (see run_view).
struct Runner {
    const Case* method;
    gem::gpu::FrameRenderer renderer;
    std::vector<double> frame_ms;
    std::vector<double> stone_ms;
};

gem::gpu::FrameRenderer make_renderer(const Case& c, const View& v, const gem::Stone& stone,
                                      const std::shared_ptr<const gem::Database>& db,
                                      const gem::Environment& environment,
                                      const gem::MetalMesh& ring) {
    gem::gpu::FrameSetup setup;
    setup.method = c.method;
    setup.database = c.method == "table" ? db : nullptr;
    setup.stone = stone;
    setup.material = stone.material;
    setup.shading.lights = {{{20.0, 60.0, 40.0}, false, {2.0, 2.0, 2.0}},
                            {{-30.0, 50.0, -20.0}, false, {1.5, 1.5, 1.5}}};
    setup.trace.max_depth = c.depth;
    setup.trace_dispersion = c.dispersion;
    setup.trace_search =
        c.triangles ? gem::gpu::ExitSearch::triangles : gem::gpu::ExitSearch::measured;
    setup.table.blend = c.blend;
    setup.visibility_pass =
        c.by_facet ? gem::gpu::VisibilityPass::off : gem::gpu::VisibilityPass::where_it_pays;
    setup.environment = &environment;
    if (v.ring) setup.ring = &ring;
    auto renderer = gem::gpu::FrameRenderer::make(std::move(setup));
    if (!renderer) {
        std::fprintf(stderr, "bench_gpu: %s\n", renderer.error().c_str());
        std::exit(1);
    }
    return std::move(renderer).value();
}

// One frame of one method straight into `target`, timed: the whole frame and its stone pass
// alone.
gem::gpu::FrameStats draw(gem::gpu::FrameRenderer& renderer, const gem::gpu::FrameView& view,
                          const gem::gpu::RenderTarget& target) {
    return *gem::bench::compose(
                "bench_gpu",
                {.renderer = &renderer, .view = view, .wait = gem::gpu::FrameWait::passes}, target)
                .stats;
}

double median(std::vector<double> samples) {
    std::sort(samples.begin(), samples.end());
    return samples[samples.size() / 2];
}

// Every method on one view, frame by frame in turn (phong, table, …, trace, then the next
// frame), so that a noisy machine slows them alike: each method's ratio to phong is the median
// of its per-frame ratios to the phong frame drawn just before it.
std::vector<Runner> run_view(const std::vector<Case>& cases, const View& v, const gem::Stone& stone,
                             const std::shared_ptr<const gem::Database>& db,
                             const gem::Environment& environment, const gem::MetalMesh& ring,
                             int frames) {
    std::vector<Runner> runners;
    runners.reserve(cases.size());
    for (const Case& c : cases) {
        runners.push_back({&c, make_renderer(c, v, stone, db, environment, ring), {}, {}});
    }
    auto target = gem::gpu::RenderTarget::make(v.width, v.height);
    for (int f = -1; f < frames; ++f) {  // frame −1 warms up (programs, first views)
        for (Runner& r : runners) {
            const gem::gpu::FrameStats stats =
                draw(r.renderer, view_for(v, r.renderer, ring, stone, f), target.value());
            if (f < 0) continue;
            r.frame_ms.push_back(stats.cpu_ms);
            r.stone_ms.push_back(stats.stone_ms);
        }
    }
    return runners;
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 6;
    bool quick = false;
    std::string only;
    std::string methods;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) frames = std::atoi(argv[++i]);
        if (std::strcmp(argv[i], "--quick") == 0) quick = true;
        if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) only = argv[++i];
        if (std::strcmp(argv[i], "--methods") == 0 && i + 1 < argc) methods = argv[++i];
    }
    if (quick) frames = std::min(frames, 3);
    frames = std::max(frames, 1);
    auto context = gem::gpu::EglContext::headless();
    if (!context) {
        std::fprintf(stderr, "bench_gpu: %s\n", context.error().c_str());
        return 1;
    }
    std::printf("GL: %s\n", context.value().description().c_str());
    auto stone = gem::make_cut(gem::default_cut_params(gem::CutShape::round_brilliant),
                               *gem::find_material("diamond"));
    const gem::Environment environment = gem::Environment::studio();
    auto ring = gem::make_ring({}, stone.value());

    std::vector<View> views = {{"1024² zoom 1", 1024, 1024, 1.0, 40.0, false},
                               {"1024² zoom 0.62", 1024, 1024, 0.62, 40.0, false},
                               {"1024² zoom 0.5", 1024, 1024, 0.5, 40.0, false},
                               {"1024² zoom 0.25", 1024, 1024, 0.25, 40.0, false},
                               {"kiosk 1080p ring", 1920, 1080, 1.0, 40.0, true}};
    std::vector<Case> cases = {
        {"phong", "phong"},
        {"table nearest", "table"},
        {"table blend", "table", true},
        {"trace depth 7", "trace"},
        {"trace depth 7 by facet", "trace", false, kTraceDepth, TraceDispersion::none, false, true},
        {"trace depth 8", "trace", false, kKioskDepth},
        {"trace 7 fire 1st order", "trace", false, kTraceDepth, TraceDispersion::first_order},
        {"trace 7 fire exact", "trace", false, kTraceDepth, TraceDispersion::exact}};
    if (quick) views = {views[0], views[3]};

    auto heart =
        gem::make_cut(gem::default_cut_params(gem::CutShape::heart), *gem::find_material("ruby"));
    struct Subject {
        const gem::Stone* stone;
        std::vector<View> views;
        std::vector<Case> cases;
    };
    std::vector<Subject> subjects = {
        {&stone.value(), views, cases},
        {&heart.value(),
         {{"heart 1024² z 1", 1024, 1024, 1.0, 40.0, false},
          {"heart 1024² z 0.5", 1024, 1024, 0.5, 40.0, false}},
         {{"phong", "phong"},
          {"trace depth 7", "trace"},
          {"trace 7 triangles", "trace", false, kTraceDepth, TraceDispersion::none, true}}}};
    if (quick) subjects.resize(1);
    for (Subject& st : subjects) {
        std::erase_if(st.cases, [&](const Case& c) {
            return c.method != "phong" && std::string(c.name).find(methods) == std::string::npos;
        });
    }
    // The database takes most of a short run to build: only when a table method draws.
    const bool tables = std::ranges::any_of(subjects.front().cases,
                                            [](const Case& c) { return c.method == "table"; });
    const auto db = tables ? build_database(stone.value(), kTraceDepth) : nullptr;

    std::printf("%-18s %-24s %9s %9s %9s %8s %10s %8s\n", "view", "method", "ms/frame", "stone ms",
                "stone Mpx", "stone %", "ms/Mpx", "×phong");
    for (const Subject& st : subjects) {
        for (const View& v : st.views) {
            if (!only.empty() && std::string(v.name).find(only) == std::string::npos) continue;
            // The stone's pixels at the turn's middle frame (a turn of a few degrees barely moves
            // its outline).
            auto probe = gem::gpu::FrameRenderer::make([&] {
                gem::gpu::FrameSetup s;
                s.method = "phong";
                s.stone = *st.stone;
                s.environment = &environment;
                if (v.ring) s.ring = &ring.value();
                return s;
            }());
            const gem::Camera middle =
                camera_for(v, probe.value(), ring.value(), *st.stone, frames / 2);
            const long pixels = stone_pixels(*st.stone, middle);
            const double mpx = pixels / 1e6;
            const std::vector<Runner> runners =
                run_view(st.cases, v, *st.stone, db, environment, ring.value(), frames);
            const Runner& phong = runners.front();  // every subject's first case
            for (const Runner& r : runners) {
                std::vector<double> ratios;
                for (std::size_t f = 0; f < r.frame_ms.size(); ++f) {
                    ratios.push_back(r.frame_ms[f] / phong.frame_ms[f]);
                }
                const double stone_ms = median(r.stone_ms);
                std::printf("%-18s %-24s %9.1f %9.1f %9.3f %7.1f%% %10.1f %8.2f\n", v.name,
                            r.method->name, median(r.frame_ms), stone_ms, mpx,
                            100.0 * pixels / (static_cast<double>(v.width) * v.height),
                            stone_ms / mpx, median(ratios));
                std::fflush(stdout);
            }
        }
    }
    return 0;
}
