// What a piece's frame costs against the solitaire's, printed, not asserted: each piece as the
// kiosk draws it (kiosk/stage/stone_scene.hpp: the shipped config's first look, the trace, the
// start view framed as the kiosk frames it), the pieces drawn in turn frame by frame so that
// the machine's load falls on all of them alike. Per piece: the median whole frame, its stone
// passes alone (FrameWait::passes: its depth pass and its shading) and the CPU's time issuing that
// pass's draws (a call per stone), the metal pass, and its stone pixels (centre and others: pixels
// whose orthographic ray meets a stone, found on the CPU by each stone's own intersector; the metal
// in front of a stone is not subtracted; and the stone pixels shaded and kept, StonePixels). A
// piece of several stones is drawn twice: with every stone traced as configured, and with its small
// stones' models chosen as the kiosk chooses them (gpu/stone_models.hpp), the choice printed. A
// piece with a kind of stone whose tables are given (--tables, as the kiosk builds them for a
// non-convex stone: gpu/piece_tables.hpp) is drawn a third time, that kind from its tables.
// Last, per piece, the time to make again what its stones see, as a change of look does, and the
// metal pass and stone passes of a still view's frame, whose metal follows its reflections and
// whose stones their exits through the piece (metal_sight.glsl, stone_sight.glsl).
//
// The stones are shaded through the visibility pass where the frame allows it and it pays
// (FrameSetup::visibility_pass); --facet-by-facet draws them without it, to compare.
// --samples N draws the moving frames multisampled, as the kiosk's picture does (picture.msaa);
// a still view's frames are single samples there too. A multisampled frame of one stone goes
// facet by facet; --all-by-visibility draws it by visibility too.
//
//   bench_pieces [--size WxH] [--frames N] [--samples N] [--exact-fire]
//                [--facet-by-facet | --all-by-visibility] [--tables FILE.gemdb ...]
//                [piece.toml ...]
//   (default: config/pieces/solitaire.toml, halo.toml and eternity-band.toml, 1920x1080,
//    9 frames each)
#include <GLES3/gl3.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "cpu/piece_tracer.hpp"
#include "gemdb/reader.hpp"
#include "gemdb/sections.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "piece/piece_file.hpp"
#include "scene/scene.hpp"
#include "stage/start_view.hpp"
#include "stage/stone_scene.hpp"
#include "trace/intersector.hpp"

#include "bench_frame.hpp"
#include "bench_support.hpp"

namespace {

constexpr const char* kProgram = "bench_pieces";
[[noreturn]] void fail(const std::string& why) {
    gem::bench::fail(kProgram, why);
}
template <class T>
T must(gem::Result<T> r) {
    return gem::bench::must(kProgram, std::move(r));
}
gem::gpu::ComposedFrame compose(const gem::gpu::FrameRequest& request,
                                const gem::gpu::RenderTarget& target) {
    return gem::bench::compose(kProgram, request, target);
}

using gem::bench::median;

struct StonePixels {
    long centre = 0;  // pixels where the centre stone is met
    long others = 0;  // pixels where another stone is met and the centre is not
    // The stone fragments a frame shades that draws the stones first (in the piece's order,
    // depth-tested) and the metal after, and those of them the picture keeps (the nearest
    // stone, with no metal in front): the frame's depth pass (StoneMethod::draw_depth) shades
    // only the kept ones, and the difference is what it saves.
    long shaded = 0;
    long kept = 0;
    // The 4×4 pixel blocks holding a kept stone pixel, and the sum over them of the facets their
    // kept pixels see (each stone's own): a block is shaded once per facet it meets where each
    // facet is drawn apart (a fragment shader runs on whole blocks, its lanes outside the facet
    // idle), once where a pass shades whatever stone each pixel sees. Their ratio bounds what
    // such a pass saves on shader runs; the GPU's facets are triangles, so it is more.
    long blocks = 0;
    long block_facets = 0;
};

// The stones' pixels, each stone looked for only inside its bounding square, and the metal
// tested where a stone is met.
StonePixels stone_pixels(const gem::Piece& piece, const gem::Camera& camera) {
    const int w = camera.width(), h = camera.height();
    const double none = std::numeric_limits<double>::infinity();
    std::vector<double> depth(static_cast<std::size_t>(w) * h, none);
    std::vector<std::uint8_t> centre(depth.size(), 0);
    std::vector<std::uint32_t> seen(depth.size(), 0);  // 1 + stone << 16 | facet, nearest
    StonePixels count;
    for (std::size_t i = 0; i < piece.stones.size(); ++i) {
        const gem::Stone& stone = piece.stone_of(i);
        const gem::Placement& at = piece.stones[i].placement;
        const auto intersector = gem::make_intersector(stone);
        const double radius = gem::bounding_radius(stone.vertices);
        // The stone's centre on screen, from the rays of the two image corners.
        const gem::Ray corner = camera.ray(0.0, 0.0);
        const glm::dvec3 offset = at.position - corner.origin;
        const double px = glm::dot(offset, camera.right()) / camera.pixel_size();
        const double py = -glm::dot(offset, camera.up()) / camera.pixel_size();
        const double r_px = radius / camera.pixel_size() + 1.0;
        const int x0 = std::max(0, static_cast<int>(px - r_px));
        const int x1 = std::min(w, static_cast<int>(px + r_px) + 1);
        const int y0 = std::max(0, static_cast<int>(py - r_px));
        const int y1 = std::min(h, static_cast<int>(py + r_px) + 1);
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const gem::Ray ray = camera.ray(x + 0.5, y + 0.5);
                gem::SurfaceHit hit;
                // A placement turns and moves, so t is the same in the stone's frame.
                if (!intersector->next_entry(at.to_stone(ray.origin),
                                             at.direction_to_stone(ray.direction), gem::kNoFacet,
                                             hit)) {
                    continue;
                }
                const std::size_t p = static_cast<std::size_t>(y) * w + x;
                if (i == 0) centre[p] = 1;
                if (hit.t < depth[p]) {
                    ++count.shaded;
                    depth[p] = hit.t;
                    seen[p] = 1 + (static_cast<std::uint32_t>(i) << 16 | hit.facet);
                }
            }
        }
    }
    const gem::Stone metal = gem::metal_as_solid(piece.metal);
    const auto metal_hits = metal.triangles.empty() ? nullptr : gem::make_bvh_intersector(metal);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * w + x;
            if (depth[p] == none) continue;
            count.centre += centre[p];
            count.others += 1 - centre[p];
            const gem::Ray ray = camera.ray(x + 0.5, y + 0.5);
            gem::SurfaceHit hit;
            const bool behind_metal =
                metal_hits != nullptr &&
                metal_hits->next_entry(ray.origin, ray.direction, gem::kNoFacet, hit) &&
                hit.t < depth[p];
            count.kept += behind_metal ? 0 : 1;
            if (behind_metal) seen[p] = 0;
        }
    }
    for (int by = 0; by < h; by += 4) {
        for (int bx = 0; bx < w; bx += 4) {
            std::uint32_t facets[16];
            int n = 0;
            for (int y = by; y < std::min(by + 4, h); ++y) {
                for (int x = bx; x < std::min(bx + 4, w); ++x) {
                    const std::uint32_t id = seen[static_cast<std::size_t>(y) * w + x];
                    if (id != 0 && std::find(facets, facets + n, id) == facets + n) {
                        facets[n++] = id;
                    }
                }
            }
            count.blocks += n > 0;
            count.block_facets += n;
        }
    }
    return count;
}

struct Subject {
    std::string file;
    bool chosen = false;  // small stones' models chosen (gpu/stone_models.hpp), else configured
    bool tabled = false;  // a kind drawn from its tables (--tables)
    std::shared_ptr<const gem::Piece> piece;
    std::unique_ptr<gem::kiosk::StoneScene> scene;
    gem::gpu::FrameView view;  // the start view (its tables' views waited for)
    gem::Camera camera;        // ... its camera
    std::vector<double> frame_ms;
    std::vector<double> stone_ms;
    std::vector<double> metal_ms;
    std::vector<double> submit_ms;
    std::vector<double> depth_ms;
    std::vector<double> still_metal_ms;  // a still view's frame's metal pass
    std::vector<double> still_stone_ms;  // ... and its stone passes
    double sight_ms = 0.0;               // what the stones see made again, as a new look makes it
};

}  // namespace

int main(int argc, char** argv) {
    int width = 1920, height = 1080, frames = 9;
    bool exact_fire = false;
    gem::gpu::VisibilityPass visibility = gem::gpu::VisibilityPass::where_it_pays;
    int depth = 8;
    int samples = 1;
    std::vector<std::string> files;
    std::vector<std::shared_ptr<const gem::Database>> databases;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--size" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2) fail("--size WxH");
        } else if (a == "--frames" && i + 1 < argc) {
            frames = std::atoi(argv[++i]);
        } else if (a == "--depth" && i + 1 < argc) {
            depth = std::atoi(argv[++i]);
        } else if (a == "--samples" && i + 1 < argc) {
            samples = std::atoi(argv[++i]);
        } else if (a == "--exact-fire") {
            exact_fire = true;
        } else if (a == "--facet-by-facet") {
            visibility = gem::gpu::VisibilityPass::off;
        } else if (a == "--all-by-visibility") {
            visibility = gem::gpu::VisibilityPass::always;
        } else if (a == "--tables" && i + 1 < argc) {
            databases.push_back(
                std::make_shared<const gem::Database>(must(gem::Database::open(argv[++i]))));
        } else if (a.rfind("--", 0) == 0) {
            fail("unknown option " + a);
        } else {
            files.push_back(a);
        }
    }
    const std::filesystem::path pieces = std::filesystem::path(GEM_CONFIG_DIR) / "pieces";
    if (files.empty()) {
        for (const char* name : {"solitaire", "halo", "eternity-band"}) {
            files.push_back((pieces / (std::string(name) + ".toml")).string());
        }
    }
    auto context = must(gem::gpu::EglContext::headless());
    auto target = must(gem::gpu::RenderTarget::make(width, height));
    gem::gpu::PictureOptions multisampled;
    multisampled.samples = samples;
    auto picture = must(gem::gpu::HdrPicture::make(width, height, multisampled));
    if (samples > 1 && picture.samples() < 2) fail("this GL multisamples no float picture");
    // The kiosk's studio look with one key light, as bench_picture lights its ring.
    gem::kiosk::LookChoice look;
    look.lights = {{{-30.0, 80.0, 45.0}, false, {2.0, 2.0, 2.0}}};
    gem::kiosk::RenderChoice render;
    render.method = "trace";
    render.exact_fire = exact_fire;
    render.depth = depth;

    std::vector<Subject> subjects;
    for (const std::string& file : files) {
        const auto piece = std::make_shared<const gem::Piece>(must(gem::load_piece(file)));
        // Each piece as configured, then with its small stones' models chosen as the kiosk
        // chooses them (a loose stone or a solitaire has none to choose).
        // The kinds whose tables were given.
        std::vector<std::shared_ptr<const gem::Database>> kind_tables(piece->kinds.size());
        bool any_tables = false;
        for (std::size_t k = 0; k < piece->kinds.size(); ++k) {
            for (const auto& database : databases) {
                if (gem::same_stored_stone(database->stone(), piece->kinds[k])) {
                    kind_tables[k] = database;
                    any_tables = true;
                }
            }
        }
        for (int pass = 0; pass < 3; ++pass) {
            const bool chosen = pass > 0, tabled = pass == 2;
            if (chosen && piece->stones.size() < 2) continue;
            if (tabled && !any_tables) continue;
            Subject s;
            s.file = std::filesystem::path(file).filename().string();
            s.chosen = chosen;
            s.tabled = tabled;
            s.piece = piece;
            gem::kiosk::CatalogueStone entry;
            entry.name = piece->name;
            entry.piece = file;
            entry.placed = piece;
            s.scene = must(gem::kiosk::StoneScene::make(
                entry, look, render,
                tabled ? kind_tables : std::vector<std::shared_ptr<const gem::Database>>{}));
            if (chosen) {
                for (const std::string& line :
                     must(s.scene->choose_stone_models({width, height}))) {
                    std::printf("%s: %s\n", s.file.c_str(), line.c_str());
                }
            }
            s.scene->renderer().set_visibility_pass(visibility);
            s.view = s.scene->frame_view(gem::kiosk::kStartView, {width, height});
            s.view.wait_for_views = true;
            s.camera = must(s.scene->camera(gem::kiosk::kStartView, {width, height}));
            subjects.push_back(std::move(s));
        }
    }
    for (int f = -1; f < frames; ++f) {
        for (Subject& s : subjects) {
            // A moving frame, into the multisampled picture as the kiosk's, or straight into the
            // target at one sample; then a still view's frame, single samples.
            if (samples > 1) picture.begin_frame(false);
            const gem::gpu::FrameStats stats =
                *compose({.renderer = &s.scene->renderer(),
                          .view = s.view,
                          .wait = gem::gpu::FrameWait::passes,
                          .picture = samples > 1 ? &picture : nullptr},
                         target)
                     .stats;
            if (f < 0) continue;  // the first frame compiles and uploads
            s.frame_ms.push_back(stats.cpu_ms);
            s.stone_ms.push_back(stats.stone_ms);
            s.metal_ms.push_back(stats.metal_ms);
            s.submit_ms.push_back(stats.stone_submit_ms);
            s.depth_ms.push_back(stats.stone_depth_ms);
            gem::gpu::StillFrame still;
            still.index = f + 1;
            const gem::gpu::FrameStats still_stats = *compose({.renderer = &s.scene->renderer(),
                                                               .view = s.view,
                                                               .wait = gem::gpu::FrameWait::passes,
                                                               .still = still},
                                                              target)
                                                          .stats;
            s.still_metal_ms.push_back(still_stats.metal_ms);
            s.still_stone_ms.push_back(still_stats.stone_ms);
        }
    }
    // What the stones see (each group's cube of the metal, gpu/frame_renderer.cpp) is made when
    // the piece is loaded and again when the look's lights change (FrameRenderer::set_lights),
    // not per frame: that remaking timed, glFinish-bounded, median of 5.
    for (Subject& s : subjects) {
        std::vector<double> ms;
        for (int i = 0; i < 5; ++i) {
            glFinish();
            const auto t0 = std::chrono::steady_clock::now();
            must(s.scene->renderer().set_lights(look.lights));
            glFinish();
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count());
        }
        s.sight_ms = median(ms);
    }
    std::printf(
        "%dx%d, the kiosk's start view, trace (%s fire), moving frames at %d sample%s, stones %s, "
        "median of %d frames in turn\n",
        width, height, exact_fire ? "exact" : "first-order", std::max(1, picture.samples()),
        picture.samples() > 1 ? "s" : "",
        visibility == gem::gpu::VisibilityPass::off      ? "facet by facet"
        : visibility == gem::gpu::VisibilityPass::always ? "all by visibility"
                                                         : "by visibility where it pays",
        frames);
    std::printf(
        "%-20s %8s %7s %9s %9s %9s %9s %9s %9s %10s %10s %10s %10s %9s %9s %11s %12s %8s %13s\n",
        "piece", "models", "stones", "frame ms", "stone ms", "depth ms", "submit ms", "metal ms",
        "x first", "centre px", "others px", "shaded px", "kept px", "metal tri", "sight ms",
        "still metal", "still stones", "blocks", "facets/block");
    const double first = median(subjects.front().frame_ms);
    for (const Subject& s : subjects) {
        const StonePixels px = stone_pixels(*s.piece, s.camera);
        std::printf(
            "%-20s %8s %7zu %9.1f %9.1f %9.1f %9.2f %9.1f %9.2f %10ld %10ld %10ld %10ld %9zu "
            "%9.1f %11.1f %12.1f %8ld %13.2f\n",
            s.file.c_str(),
            s.tabled   ? "tables"
            : s.chosen ? "chosen"
                       : "config",
            s.piece->stones.size(), median(s.frame_ms), median(s.stone_ms), median(s.depth_ms),
            median(s.submit_ms), median(s.metal_ms), median(s.frame_ms) / first, px.centre,
            px.others, px.shaded, px.kept, s.piece->metal.indices.size() / 3, s.sight_ms,
            median(s.still_metal_ms), median(s.still_stone_ms), px.blocks,
            px.blocks > 0 ? static_cast<double>(px.block_facets) / px.blocks : 0.0);
    }
    return 0;
}
