// Figures of the shop window's picture (gpu/hdr_picture.hpp), printed, not asserted.
//
//  1. What each pass costs at the kiosk's 1920×1080 start view (the round diamond in its
//     parametric ring, framed as the kiosk frames it), and at zoom 0.5 (the piece at half the
//     size): the scene (its stone and metal passes shown apart) drawn at 1 sample without glare
//     and at 4× MSAA with glare 0.04, then the resolve, the still view's running mean, the
//     glare pyramid and the tone curve, each bounded by glFinish; medians of --frames frames,
//     trace (depth 8, first-order fire; at 4× MSAA also with its one stone shaded through the
//     visibility pass, which the kiosk does not choose for one stone: FrameSetup) and phong; the
//     share of a moving frame the passes after the scene take (the present pass to the screen's
//     buffer included: a back buffer that lacks this frame's changes only); and the share of the
//     picture they rewrote (around the piece and its glare's reach, hdr_picture.hpp). The bench's
//     last line is for a script to read, the trace at 4× MSAA with glare: "bench_picture: finishing
//     X% of the frame; zoom 0.5 costs R of zoom 1".
//  2. Edges against the CPU reference at 16 samples per pixel, the loose diamond at 256²
//     (zoom 1, 40° elevation, the studio, no glare, the same tone curve on both): the mean
//     8-bit error on its edge pixels (where the reference's own single centre sample is more
//     than 8 codes off its 16-sample mean: sub-pixel detail) and on all its pixels, for the
//     trace at 1 sample, at 4× MSAA, and at 4× MSAA with 16 still frames averaged.
//  3. Flicker: the same stone turning 0.1° a frame for --turn frames; the mean change of a
//     pixel's 8-bit luma from frame to frame, for the trace at 1 sample, 4× MSAA, 4× MSAA with
//     glare, and for the CPU reference's frames (16 samples per pixel).
//  4. The present pass (kiosk/display/present_pass.hpp) over the whole 1920×1080 picture:
//     its bytes copied undecoded against decoded and encoded again by the shader, drawn in
//     turn, medians and the median of their frame-by-frame ratios.
//
//  5. The glare cut where the display shows none of it (PictureOptions::glare_cut) against the
//     glare wherever its filters reach, the trace at 4× MSAA with glare 0.04 at the kiosk's
//     1920×1080 start view, a moving frame and the still view's 16th: mean and largest ΔE00
//     over the whole picture, the largest 8-bit code apart, and the share of the picture
//     each rewrote; and of the 32-pixel tiles the cut one rewrote, the share that hold a pixel
//     off the background's colour (in the moving frame, or the one before it): how near the
//     tiles the passes after the scene run over come to those they must.
//
//   bench_picture [--frames N] [--turn N]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include "cpu/reference_render.hpp"
#include "display/present_pass.hpp"
#include "geometry/cuts.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/pixel_rect.hpp"
#include "optics/colour.hpp"
#include "optics/material.hpp"
#include "picture/image_error.hpp"
#include "piece/ring_mesh.hpp"
#include "stage/framing.hpp"
#include "stage/start_view.hpp"
#include "util/elapsed.hpp"

#include "bench_frame.hpp"
#include "bench_support.hpp"

namespace {

using gem::gpu::TraceDispersion;

constexpr const char* kProgram = "bench_picture";
template <class T>
T must(gem::Result<T> r) {
    return gem::bench::must(kProgram, std::move(r));
}
gem::gpu::ComposedFrame compose(const gem::gpu::FrameRequest& request,
                                const gem::gpu::RenderTarget& target) {
    return gem::bench::compose(kProgram, request, target);
}

using gem::bench::median;

// The screen's buffer as the DRM backend draws it: plain 8-bit RGBA, not sRGB.
struct ScreenBuffer {
    ScreenBuffer(int width, int height)
        : colour(gem::gpu::make_texture_2d(GL_RGBA8, width, height, GL_NEAREST)),
          framebuffer(gem::gpu::make_framebuffer_with(colour.get())),
          size(width, height) {}
    gem::gpu::Texture colour;
    gem::gpu::Framebuffer framebuffer;
    glm::ivec2 size;
};

// One present pass into `screen`, over `region` (nullopt: whole), bounded by glFinish.
double time_present(gem::kiosk::PresentPass& pass, const gem::gpu::RenderTarget& picture,
                    const ScreenBuffer& screen, const gem::gpu::TileSet* region) {
    glBindFramebuffer(GL_FRAMEBUFFER, screen.framebuffer.get());
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    must(pass.draw(picture, 0, screen.size, region));
    glFinish();
    return gem::ms_since(t0);
}

gem::gpu::PictureOptions options(int samples, double glare, int still_frames) {
    gem::gpu::PictureOptions o;
    o.samples = samples;
    o.glare = glare;
    o.still_frames = still_frames;
    return o;
}

const std::vector<gem::Light> kLights = {{{-30.0, 80.0, 45.0}, false, {2.0, 2.0, 2.0}}};

gem::gpu::FrameRenderer make_renderer(const std::string& method, const gem::Stone& stone,
                                      const gem::Environment& environment,
                                      const gem::MetalMesh* ring) {
    gem::gpu::FrameSetup setup;
    setup.method = method;
    setup.stone = stone;
    setup.material = stone.material;
    setup.shading.lights = kLights;
    setup.trace.max_depth = 8;
    setup.trace_dispersion = ring ? TraceDispersion::first_order : TraceDispersion::none;
    setup.environment = &environment;
    setup.cube_face = 256;
    setup.ring = ring;
    return must(gem::gpu::FrameRenderer::make(std::move(setup)));
}

// One configuration's medians: the scene (stone, ring and background), its stone and metal
// passes within it, and each finishing pass.
struct PassCosts {
    double scene = 0.0, stone = 0.0, metal = 0.0, resolve = 0.0, mean = 0.0, glare = 0.0,
           tone = 0.0, present = 0.0;
    double rewritten = 0.0;  // share of the picture a moving frame's tone pass rewrote
    // A moving frame: the scene and the passes after it (the still view's mean is not in it).
    double total() const { return scene + finishing(); }
    double finishing() const { return resolve + glare + tone + present; }
};

// One frame of `view` through `hdr` as the kiosk composes it, begun `still` or moving, its scene
// traced as a still frame where `as_still`, else as a moving frame.
gem::gpu::ComposedFrame draw_view(gem::gpu::FrameRenderer& renderer,
                                  const gem::kiosk::Framing& framing,
                                  const gem::kiosk::ViewState& view, bool still, bool as_still,
                                  gem::gpu::HdrPicture& hdr, const gem::gpu::RenderTarget& picture,
                                  gem::gpu::FrameWait wait) {
    hdr.begin_frame(still);
    gem::gpu::FrameRequest request{
        .renderer = &renderer,
        .view = gem::gpu::FrameView{.camera = gem::kiosk::framed_camera(view, framing),
                                    .framing_mm = renderer.scene_radius_mm()},
        .wait = wait,
        .picture = &hdr};
    if (!as_still) request.still = gem::gpu::StillFrame{};
    return compose(request, picture);
}

PassCosts time_passes(gem::gpu::FrameRenderer& renderer, const gem::kiosk::Framing& framing,
                      double zoom, int samples, double glare, int frames,
                      const gem::gpu::RenderTarget& picture, gem::kiosk::PresentPass& pass,
                      const ScreenBuffer& screen) {
    const int w = picture.width(), h = picture.height();
    auto hdr = must(gem::gpu::HdrPicture::make(w, h, options(samples, glare, 16)));
    std::vector<double> scene, stone, metal, resolve, mean, glare_ms, tone, present, rewritten;
    for (int f = -1; f < frames; ++f) {
        gem::kiosk::ViewState view = gem::kiosk::kStartView;
        view.zoom = zoom;
        // Odd frames still (the running mean's pass), even ones turned.
        view.azimuth_deg += (f / 2) * 1.0;
        // Its still frames traced as moving ones: what the running mean's pass adds is timed.
        const gem::gpu::ComposedFrame frame = draw_view(renderer, framing, view, f % 2 == 1, false,
                                                        hdr, picture, gem::gpu::FrameWait::passes);
        const gem::gpu::FrameStats& drawn = *frame.stats;
        const gem::gpu::FinishTimes& t = frame.finish;
        const double present_ms = time_present(pass, picture, screen, &hdr.target_region());
        if (f < 0) continue;
        scene.push_back(drawn.cpu_ms);
        stone.push_back(drawn.stone_ms);
        metal.push_back(drawn.metal_ms);
        (f % 2 == 1 ? mean : resolve).push_back(t.resolve_ms);
        glare_ms.push_back(t.glare_ms);
        tone.push_back(t.tone_ms);
        if (f % 2 == 0) {
            present.push_back(present_ms);
            rewritten.push_back(static_cast<double>(hdr.target_region().area()) / (double(w) * h));
        }
    }
    // The resolve is the moving frames' (a blit); mean is what the running mean's pass adds
    // on still frames.
    return {median(scene),
            median(stone),
            median(metal),
            median(resolve),
            median(mean) - median(resolve),
            median(glare_ms),
            median(tone),
            median(present),
            median(rewritten)};
}

// The line a script reads: the trace at 4× MSAA with glare, the passes after the scene as a
// share of the frame at zoom 1, and the frame at zoom 0.5 against zoom 1.
struct Summary {
    double finishing_share = 0.0;
    double half_zoom_ratio = 0.0;
};

Summary pass_costs(const gem::Stone& stone, const gem::Environment& environment, int frames) {
    const int w = 1920, h = 1080;
    const auto ring = must(gem::make_ring({}, stone));
    std::printf(
        "\n1. passes at %d×%d, the kiosk's start view of the diamond in its ring and the same "
        "at zoom 0.5 (median ms of %d frames; each pass bounded by glFinish; finishing: the "
        "passes after the scene, share of a moving frame)\n",
        w, h, frames);
    std::printf("%-6s %-8s %-12s %7s %7s %7s %8s %7s %7s %7s %8s %8s %10s %10s\n", "zoom", "method",
                "picture", "scene", "stone", "metal", "resolve", "mean", "glare", "tone", "present",
                "total", "finishing", "rewritten");
    auto picture = must(gem::gpu::RenderTarget::make(w, h));
    auto pass = must(gem::kiosk::PresentPass::make());
    const ScreenBuffer screen(w, h);
    struct Look {
        const char* name;
        int samples;
        double glare;
        // The kiosk's (where_it_pays: this one stone's multisampled frames facet by facet),
        // or always by visibility (the trace's only, to show what that choice saves).
        gem::gpu::VisibilityPass visibility;
    };
    using gem::gpu::VisibilityPass;
    const Look looks[] = {{"1 sample", 1, 0.0, VisibilityPass::where_it_pays},
                          {"4×, glare", 4, 0.04, VisibilityPass::where_it_pays},
                          {"4×, visibility", 4, 0.04, VisibilityPass::always}};
    double kiosk_total[2] = {};  // trace, 4× MSAA and glare: zoom 1, zoom 0.5
    double kiosk_finishing = 0.0;
    for (const char* method : {"phong", "trace"}) {
        auto renderer = make_renderer(method, stone, environment, &ring);
        std::vector<glm::dvec3> ring_points(ring.positions.begin(), ring.positions.end());
        const gem::kiosk::Framing framing =
            gem::kiosk::frame_ring(stone.vertices, ring_points, gem::kiosk::kStartView, {w, h},
                                   renderer.scene_radius_mm(), 0.25);
        for (int z = 0; z < 2; ++z) {
            const double zoom = z == 0 ? 1.0 : 0.5;
            for (const Look& look : looks) {
                const bool trace = std::strcmp(method, "trace") == 0;
                const bool kiosks = look.visibility == VisibilityPass::where_it_pays;
                if (!kiosks && !trace) continue;
                renderer.set_visibility_pass(look.visibility);
                const PassCosts c = time_passes(renderer, framing, zoom, look.samples, look.glare,
                                                frames, picture, pass, screen);
                std::printf(
                    "%-6.2g %-8s %-12s %7.1f %7.1f %7.1f %8.1f %7.1f %7.1f %7.1f %8.1f %8.1f "
                    "%9.0f%% %9.0f%%\n",
                    zoom, method, look.name, c.scene, c.stone, c.metal, c.resolve, c.mean, c.glare,
                    c.tone, c.present, c.total(), 100.0 * c.finishing() / c.total(),
                    100.0 * c.rewritten);
                std::fflush(stdout);
                if (trace && look.samples == 4 && kiosks) {
                    kiosk_total[z] = c.total();
                    if (z == 0) kiosk_finishing = c.finishing() / c.total();
                }
            }
        }
    }
    return {kiosk_finishing, kiosk_total[1] / kiosk_total[0]};
}

struct Frames {
    std::vector<std::vector<float>> luma;  // 8-bit luma per pixel, per frame
    std::vector<gem::Image> images;        // display-linear
};

float luma8(const glm::vec4& display_linear) {
    const glm::u8vec3 c = gem::linear_to_srgb8(glm::dvec3(display_linear));
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

void add_frame(Frames& out, gem::Image image) {
    std::vector<float> l;
    l.reserve(image.pixels.size());
    for (const glm::vec4& p : image.pixels) l.push_back(luma8(p));
    out.luma.push_back(std::move(l));
    out.images.push_back(std::move(image));
}

gem::CameraSettings turned(int frame) {
    gem::CameraSettings cs;
    cs.elevation_deg = 40.0;
    cs.azimuth_deg = 0.1 * frame;
    return cs;
}

Frames gpu_frames(const gem::Stone& stone, const gem::Environment& environment, int size, int count,
                  const gem::gpu::PictureOptions& o) {
    auto renderer = make_renderer("trace", stone, environment, nullptr);
    auto hdr = must(gem::gpu::HdrPicture::make(size, size, o));
    auto picture = must(gem::gpu::RenderTarget::make(size, size));
    Frames out;
    for (int f = 0; f < count; ++f) {
        // A still view (count 1 with still_frames > 1) is averaged over its frames.
        const int repeats = count == 1 ? o.still_frames : 1;
        for (int r = 0; r < repeats; ++r) {
            hdr.begin_frame(count == 1 && o.still_frames > 1);
            compose(
                {.renderer = &renderer,
                 .view = gem::gpu::FrameView{.camera = turned(f),
                                             .framing_mm = gem::bounding_radius(stone.vertices)},
                 .wait = gem::gpu::FrameWait::frame,
                 .picture = &hdr},
                picture);
        }
        add_frame(out, picture.read());
    }
    return out;
}

Frames cpu_frames(const gem::Stone& stone, const gem::Environment& environment, int size, int count,
                  int spp) {
    Frames out;
    gem::RenderSettings s;
    s.width = s.height = size;
    s.samples_per_pixel = spp;
    s.shading.lights = kLights;
    s.trace.max_depth = 8;
    for (int f = 0; f < count; ++f) {
        s.camera = turned(f);
        const gem::Image linear = must(gem::render_reference(stone, environment, s));
        add_frame(out, gem::to_display(linear, {}));
    }
    return out;
}

double flicker(const Frames& frames) {
    double sum = 0.0;
    long n = 0;
    for (std::size_t f = 1; f < frames.luma.size(); ++f) {
        for (std::size_t i = 0; i < frames.luma[f].size(); ++i) {
            sum += std::abs(frames.luma[f][i] - frames.luma[f - 1][i]);
            ++n;
        }
    }
    return n > 0 ? sum / n : 0.0;
}

void edges_and_flicker(const gem::Stone& stone, const gem::Environment& environment, int turn) {
    const int size = 256;
    const Frames reference = cpu_frames(stone, environment, size, 1, 16);
    const Frames centre = cpu_frames(stone, environment, size, 1, 1);
    std::vector<bool> edge(reference.luma[0].size()), on_stone(edge.size());
    long edges = 0, stone_px = 0;
    for (std::size_t i = 0; i < edge.size(); ++i) {
        edge[i] = std::abs(centre.luma[0][i] - reference.luma[0][i]) > 8.0f;
        on_stone[i] = reference.images[0].pixels[i].w > 0.0f;
        edges += edge[i];
        stone_px += on_stone[i];
    }
    std::printf(
        "\n2. edges against the CPU reference at 16 spp, %d² (%ld stone pixels, %ld of "
        "them edge pixels)\n",
        size, stone_px, edges);
    std::printf("%-34s %14s %14s\n", "trace", "edge px error", "stone px error");
    struct Variant {
        const char* name;
        int samples;
        int still;
    };
    for (const Variant& v : {Variant{"1 sample", 1, 1}, Variant{"4× MSAA", 4, 1},
                             Variant{"4× MSAA, 16 still frames", 4, 16}}) {
        const Frames g = gpu_frames(stone, environment, size, 1, options(v.samples, 0.0, v.still));
        double e_edge = 0.0, e_stone = 0.0;
        for (std::size_t i = 0; i < edge.size(); ++i) {
            const double d = std::abs(g.luma[0][i] - reference.luma[0][i]);
            if (edge[i]) e_edge += d;
            if (on_stone[i]) e_stone += d;
        }
        std::printf("%-34s %14.2f %14.2f\n", v.name, e_edge / std::max(edges, 1L),
                    e_stone / std::max(stone_px, 1L));
    }
    std::printf(
        "%-34s %14.2f %14s\n", "(CPU reference at 1 spp)",
        [&] {
            double e = 0.0;
            for (std::size_t i = 0; i < edge.size(); ++i) {
                if (edge[i]) e += std::abs(centre.luma[0][i] - reference.luma[0][i]);
            }
            return e / std::max(edges, 1L);
        }(),
        "");

    std::printf(
        "\n3. flicker: %d frames turning 0.1° a frame, %d², mean |Δ luma| per pixel "
        "and frame (8-bit codes)\n",
        turn, size);
    const Frames cpu = cpu_frames(stone, environment, size, turn, 16);
    struct Run {
        const char* name;
        gem::gpu::PictureOptions options;
    };
    for (const Run& r :
         {Run{"trace, 1 sample", options(1, 0.0, 1)}, Run{"trace, 4× MSAA", options(4, 0.0, 1)},
          Run{"trace, 4× MSAA, glare 0.04", options(4, 0.04, 1)}}) {
        std::printf("%-34s %8.3f\n", r.name,
                    flicker(gpu_frames(stone, environment, size, turn, r.options)));
    }
    std::printf("%-34s %8.3f\n", "CPU reference, 16 spp", flicker(cpu));
}

}  // namespace

void present_copies(int frames) {
    const int w = 1920, h = 1080;
    std::printf(
        "\n4. the present pass over the whole %d×%d picture (median ms of %d frames, "
        "drawn in turn)\n",
        w, h, frames);
    if (gem::kiosk::PresentPass::supported_copy() != gem::kiosk::PresentPass::Copy::bytes) {
        std::printf("this GL cannot skip the sRGB decode: only the re-encoding copy runs\n");
        return;
    }
    const auto picture = must(gem::gpu::RenderTarget::make(w, h));
    auto bytes = must(gem::kiosk::PresentPass::make(gem::kiosk::PresentPass::Copy::bytes));
    auto reencode = must(gem::kiosk::PresentPass::make(gem::kiosk::PresentPass::Copy::reencode));
    const ScreenBuffer screen(w, h);
    std::vector<double> bytes_ms, reencode_ms, ratio;
    for (int f = -1; f < frames; ++f) {
        const double b = time_present(bytes, picture, screen, nullptr);
        const double r = time_present(reencode, picture, screen, nullptr);
        if (f < 0) continue;
        bytes_ms.push_back(b);
        reencode_ms.push_back(r);
        ratio.push_back(b / r);
    }
    std::printf("%-34s %8.2f\n%-34s %8.2f\n%-34s %8.2f\n", "bytes copied", median(bytes_ms),
                "decoded and encoded", median(reencode_ms), "ratio", median(ratio));
}

namespace {

// The start view through `hdr` after a frame turned 1° away (the first frame rewrites the
// whole picture): its moving frame's picture (`still` 0), or its still view's after `still`
// frames; `rewritten`: the last frame's share of the picture, and `region` its tiles;
// `turned`, where given, gets the frame turned 1° away.
gem::Image start_view(gem::gpu::FrameRenderer& renderer, const gem::kiosk::Framing& framing,
                      gem::gpu::HdrPicture& hdr, const gem::gpu::RenderTarget& picture, int still,
                      double& rewritten, gem::gpu::TileSet& region, gem::Image* turned = nullptr) {
    const int w = picture.width(), h = picture.height();
    for (int f = 0; f < std::max(still, 1) + 1; ++f) {
        gem::kiosk::ViewState view = gem::kiosk::kStartView;
        if (f == 0) view.azimuth_deg += 1.0;
        draw_view(renderer, framing, view, f > 1, true, hdr, picture, gem::gpu::FrameWait::frame);
        region = hdr.target_region();
        rewritten = static_cast<double>(hdr.target_region().area()) / (double(w) * h);
        if (f == 0 && turned != nullptr) *turned = picture.read();
    }
    return picture.read();
}

// Of the tiles of `region` (GL's rows, bottom up), the share holding a pixel whose 8-bit code
// differs from the background's (the picture's corner) in either picture (read top row first):
// of what the passes after the scene rewrite, what they had to.
double tiles_off_the_background(const gem::Image& a, const gem::Image& b,
                                const gem::gpu::TileSet& region) {
    const int w = a.width, h = a.height;
    const auto code = [w, h](const gem::Image& image, int x, int y) {
        return glm::ivec3(gem::linear_to_srgb8(
            glm::dvec3(image.pixels[static_cast<std::size_t>(h - 1 - y) * w + x])));
    };
    const glm::ivec3 background = code(a, 0, 0);
    gem::gpu::TileSet off(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (region.has_pixel(x, y) &&
                (code(a, x, y) != background || code(b, x, y) != background)) {
                off.mark({x, y, x + 1, y + 1});
            }
        }
    }
    const long tiles = region.tile_count();
    return tiles > 0 ? static_cast<double>(off.tile_count()) / static_cast<double>(tiles) : 0.0;
}

void glare_cut(const gem::Stone& stone, const gem::Environment& environment) {
    const int w = 1920, h = 1080;
    std::printf(
        "\n5. the glare cut where unseen against the uncut glare, trace at 4× MSAA with glare "
        "0.04, %d×%d, the start view (whole picture)\n",
        w, h);
    std::printf("%-22s %10s %10s %12s %14s %14s %18s\n", "frame", "mean ΔE00", "max ΔE00",
                "most codes", "cut rewrote", "uncut rewrote", "of its tiles, off bg");
    const auto ring = must(gem::make_ring({}, stone));
    auto renderer = make_renderer("trace", stone, environment, &ring);
    std::vector<glm::dvec3> ring_points(ring.positions.begin(), ring.positions.end());
    const gem::kiosk::Framing framing =
        gem::kiosk::frame_ring(stone.vertices, ring_points, gem::kiosk::kStartView, {w, h},
                               renderer.scene_radius_mm(), 0.25);
    const auto picture = must(gem::gpu::RenderTarget::make(w, h));
    for (const int frames : {0, 16}) {
        gem::Image shown[2];
        gem::Image turned;
        double rewritten[2] = {};
        gem::gpu::TileSet region[2];
        for (const bool cut : {true, false}) {
            gem::gpu::PictureOptions o = options(4, 0.04, 16);
            o.glare_cut = cut;
            auto hdr = must(gem::gpu::HdrPicture::make(w, h, o));
            shown[cut ? 0 : 1] =
                start_view(renderer, framing, hdr, picture, frames, rewritten[cut ? 0 : 1],
                           region[cut ? 0 : 1], cut ? &turned : nullptr);
        }
        const gem::ImageError e = must(gem::compare_images(shown[0], shown[1]));
        int most = 0;
        for (std::size_t i = 0; i < shown[0].pixels.size(); ++i) {
            const glm::ivec3 a(gem::linear_to_srgb8(glm::dvec3(shown[0].pixels[i])));
            const glm::ivec3 b(gem::linear_to_srgb8(glm::dvec3(shown[1].pixels[i])));
            const glm::ivec3 d = glm::abs(a - b);
            most = std::max({most, d.x, d.y, d.z});
        }
        // A moving frame changes the picture where the piece is this frame and was the last.
        const double tiles =
            tiles_off_the_background(shown[0], frames == 0 ? turned : shown[0], region[0]);
        std::printf("%-22s %10.4f %10.3f %12d %13.0f%% %13.0f%% %17.0f%%\n",
                    frames == 0 ? "moving" : "still, 16 frames", e.delta_e_mean, e.delta_e_max,
                    most, 100.0 * rewritten[0], 100.0 * rewritten[1], 100.0 * tiles);
    }
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 8, turn = 12;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) frames = std::atoi(argv[++i]);
        if (std::strcmp(argv[i], "--turn") == 0 && i + 1 < argc) turn = std::atoi(argv[++i]);
    }
    auto context = must(gem::gpu::EglContext::headless());
    std::printf("GL: %s\n", context.description().c_str());
    const auto stone = must(gem::make_cut(gem::default_cut_params(gem::CutShape::round_brilliant),
                                          *gem::find_material("diamond")));
    const gem::Environment environment = gem::Environment::studio();
    const Summary summary = pass_costs(stone, environment, std::max(frames, 2));
    edges_and_flicker(stone, environment, std::max(turn, 2));
    present_copies(std::max(frames, 2) * 2);
    glare_cut(stone, environment);
    std::printf("bench_picture: finishing %.0f%% of the frame; zoom 0.5 costs %.2f of zoom 1\n",
                100.0 * summary.finishing_share, summary.half_zoom_ratio);
    return 0;
}
