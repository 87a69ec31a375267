#include "gpu_render.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <vector>

#include "cpu/scene_settings.hpp"
#include "gemdb/sections.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/frame_composer.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "optics/material.hpp"
#include "picture/image.hpp"
#include "piece/metal.hpp"
#include "piece/metal_obj.hpp"
#include "piece/ring_mesh.hpp"
#include "scene/scene_build.hpp"

namespace gem {
namespace {

int fail(const std::string& message) {
    std::fprintf(stderr, "gemrender: %s\n", message.c_str());
    return 1;
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const auto i = static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5);
    return v[std::min(i, v.size() - 1)];
}

// Each database given for a piece, opened and put at the kind of stone it holds.
Result<std::vector<std::shared_ptr<const Database>>> tables_for_kinds(
    const Piece& piece, const std::vector<std::string>& files) {
    std::vector<std::shared_ptr<const Database>> tables(piece.kinds.size());
    for (const std::string& file : files) {
        auto db = Database::open(file);
        if (!db) return Error{db.error()};
        auto opened = std::make_shared<const Database>(std::move(db).value());
        bool placed = false;
        for (std::size_t k = 0; k < piece.kinds.size() && !placed; ++k) {
            if (tables[k] || !same_stored_stone(opened->stone(), piece.kinds[k])) continue;
            tables[k] = opened;
            placed = true;
        }
        if (!placed) {
            return Error{"--db " + file + ": its stone ('" + opened->stone().name +
                         "') is none of the piece's stones as the piece sizes them (gemtables "
                         "build --width-mm W, W the piece's width_mm)"};
        }
    }
    return tables;
}

}  // namespace

int render_gpu(const Scene& scene, const GpuRenderOptions& o) {
    auto context = gpu::EglContext::headless();
    if (!context) return fail(context.error());

    gpu::FrameSetup setup;
    const gpu::MethodEntry* method = gpu::find_stone_method(o.method);
    if (method == nullptr) {
        return fail("--method: unknown method '" + o.method + "' (this build has reference, " +
                    gpu::stone_method_names() + ")");
    }
    setup.method = o.method;
    if (method->needs_database) {
        if (o.piece != nullptr) return fail("--method " + o.method + " draws one loose stone");
        if (o.databases.size() != 1) {
            return fail("--method " + o.method + " needs one --db FILE.gemdb");
        }
        auto db = Database::open(o.databases.front());
        if (!db) return fail(db.error());
        setup.database = std::make_shared<const Database>(std::move(db).value());
        setup.material = setup.database->material();
    } else if (o.piece != nullptr) {
        setup.piece = o.piece;
        auto tables = tables_for_kinds(*o.piece, o.databases);
        if (!tables) return fail(tables.error());
        setup.kind_tables = std::move(tables).value();
    } else if (!o.databases.empty()) {
        return fail("--db: the " + o.method + " method draws a loose stone without tables");
    } else {
        auto stone = build_stone(scene);
        if (!stone) return fail(stone.error());
        setup.stone = std::move(stone).value();
        setup.material = setup.stone.material;
    }
    // Colour and absorption are shading-time choices, also over a database's material.
    if (scene.material.colour) setup.material.body_colour = *scene.material.colour;
    if (scene.material.absorption_per_mm) {
        setup.material.absorption_per_mm = *scene.material.absorption_per_mm;
    }
    const RenderSettings settings = render_settings(scene);
    setup.shading = settings.shading;
    setup.trace = settings.trace;
    setup.table.blend = o.blend;
    setup.trace_dispersion = o.fire == "first"      ? gpu::TraceDispersion::first_order
                             : o.fire == "exact"    ? gpu::TraceDispersion::exact
                             : o.fire == "spectral" ? gpu::TraceDispersion::spectral
                                                    : gpu::TraceDispersion::none;
    setup.table.wait_for_views = o.frames == 1;
    auto environment = build_environment(scene);
    if (!environment) return fail(environment.error());
    setup.environment = &environment.value();
    if (!scene.environment.background_is_environment) {
        setup.background_colour = glm::vec3(scene.environment.background_colour);
    }

    if (o.piece != nullptr && !o.ring.empty()) {
        return fail("--ring: a piece brings its own metal");
    }
    MetalMesh ring;
    if (!o.ring.empty()) {
        const std::optional<Metal> metal = parse_metal(o.metal);
        if (!metal) {
            return fail("--metal: unknown metal '" + o.metal + "' (" + kMetalNames + ")");
        }
        const Stone& stone = method->needs_database ? setup.database->stone() : setup.stone;
        Result<MetalMesh> made = Error{""};
        if (o.ring == "parametric") {
            RingParams params;
            params.metal = *metal;
            made = make_ring(params, stone);
        } else {
            made = load_metal_obj(o.ring, *metal, RingParams{}.roughness);
        }
        if (!made) return fail(made.error());
        ring = std::move(made).value();
        setup.ring = &ring;
    }

    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    if (!renderer) return fail(renderer.error());
    gpu::FrameRenderer& r = renderer.value();
    if (!r.sight_note().empty()) std::printf("gemrender: %s\n", r.sight_note().c_str());
    if (const std::string settled = r.method().describe(); !settled.empty()) {
        std::printf("gemrender: %s %s\n", o.method.c_str(), settled.c_str());
    }
    // A piece is framed by its bounding sphere, as the CPU reference frames it; a stone by its.
    const double framing_mm = o.piece != nullptr ? o.piece->radius_mm() : r.stone_radius_mm();
    auto target = gpu::RenderTarget::make(scene.width, scene.height);
    if (!target) return fail(target.error());
    auto hdr = gpu::HdrPicture::make(scene.width, scene.height,
                                     {.samples = o.msaa,
                                      .display = o.display,
                                      .glare = o.glare,
                                      .still_frames = o.still_frames,
                                      .spectral = o.fire == "spectral",
                                      .still_depth = o.still_depth,
                                      .still_depth_max = o.still_depth_max});
    if (!hdr) return fail(hdr.error());
    std::printf("gemrender: picture %s\n", hdr.value().describe().c_str());

    if (!o.frames_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(o.frames_dir, ec);
        if (ec) return fail("cannot create " + o.frames_dir + ": " + ec.message());
    }
    const double step = o.turn_deg != 0.0 ? o.turn_deg : 360.0 / std::max(o.frames, 1);
    std::vector<double> frame_ms;
    std::vector<double> stream_ms;
    Image last;
    for (int f = 0; f < o.frames; ++f) {
        gpu::FrameView view{.camera = scene.camera, .framing_mm = framing_mm};
        view.camera.azimuth_deg += step * f;
        // The turntable turns about +y at `step` per frame of a 60 Hz display: the stone
        // method prepares the views it reaches.
        if (o.frames > 1) view.omega = {0.0, step * std::numbers::pi / 180.0 * 60.0, 0.0};
        // One frame into the HDR picture and out through its finishing passes; `still`: the
        // view of the frame before, moved by the picture's sub-pixel jitter.
        const auto draw = [&](bool still) -> Result<gpu::FrameStats> {
            hdr.value().begin_frame(still);
            auto drawn = gpu::compose_frame({.renderer = &r, .view = view, .picture = &hdr.value()},
                                            target.value());
            if (!drawn) return Error{drawn.error()};
            return drawn.value().scene();
        };
        const auto start = std::chrono::steady_clock::now();
        auto stats = draw(false);
        if (!stats) return fail(stats.error());
        glFinish();
        frame_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
        // A single picture is a still view: as the kiosk refines one, frames a sub-pixel apart
        // averaged (not timed: the time above is one frame's).
        for (int still = 0; o.frames == 1 && o.still_frames > 1 && still < o.still_frames;
             ++still) {
            auto refined = draw(true);
            if (!refined) return fail(refined.error());
        }
        const gpu::TableFrameStats& t = stats.value().table;
        stream_ms.push_back(t.acquire_ms + t.upload_ms + t.wait_ms);
        if (o.frames > 1) {
            std::printf("frame %4d: %7.2f ms", f, frame_ms.back());
            if (method->needs_database) {
                std::printf("  streaming %6.2f ms (%u uploads, level %u%s)", stream_ms.back(),
                            t.uploads, t.level, t.exact ? "" : ", stand-in");
            }
            std::printf("\n");
        }
        if (!o.frames_dir.empty() || f + 1 == o.frames) {
            last = target.value().read();
            if (!o.frames_dir.empty()) {
                char name[32];
                std::snprintf(name, sizeof name, "frame-%04d.png", f);
                auto written = write_png(last, std::filesystem::path(o.frames_dir) / name);
                if (!written) return fail(written.error());
            }
        }
    }
    auto written = write_png(last, o.out);
    if (!written) return fail(written.error());
    double total = 0.0;
    double streaming = 0.0;
    for (std::size_t i = 0; i < frame_ms.size(); ++i) {
        total += frame_ms[i];
        streaming += stream_ms[i];
    }
    std::printf("gemrender: wrote %s (%d×%d, method %s%s%s) on %s\n",
                std::filesystem::absolute(o.out).c_str(), scene.width, scene.height,
                o.method.c_str(), o.blend ? ", blend" : "", o.ring.empty() ? "" : ", ring",
                context.value().description().c_str());
    std::printf(
        "gemrender: %zu frames: mean %.2f ms, median %.2f ms, p95 %.2f ms per frame; "
        "streaming %.1f%% of frame time\n",
        frame_ms.size(), total / static_cast<double>(frame_ms.size()), percentile(frame_ms, 0.5),
        percentile(frame_ms, 0.95), total > 0.0 ? 100.0 * streaming / total : 0.0);
    return 0;
}

}  // namespace gem
