// The shopper's still picture against the exact spectral reference, printed, not asserted
// (docs/accuracy.md, "The still picture against the spectral truth"). The scenes are
// gemrender's default scene (the studio, its lights, physical shading) with the loose
// Tolkowsky diamond at elevation 40°, azimuth 13.7° and face-up (384²), the oval sapphire at
// 55° and the heart ruby at 65° (256²).
// The reference is the CPU tracer at depth 64, 16 samples a pixel, 12 wavelengths; every
// picture goes through the same tone curve (no glare) and is compared as 8-bit sRGB, mean and
// 99th percentile CIEDE2000 over the stone's pixels (picture/image_error.hpp).
//
// Per scene: the moving picture (one frame, the trace at depth 8, exact fire, 4× MSAA), and
// the still picture after the kiosk's 16 still frames with exact fire and with spectral fire
// (each still frame its own wavelengths: gpu/hdr_picture.hpp). Then what a still frame costs
// with spectral fire against one with exact fire, the two drawn in turn frame by frame (median
// ms of --frames each, glFinish-bounded, and the median of the frame-by-frame ratios).
//
//   bench_still_picture [--frames N] [--depth D] [--min-weight W] [--still-frames N]
//                       [--still-depth D] [--cache DIR] [--only TEXT] [--size N] [--images DIR]
//                       [--reference-check N] [--reference-check-spp N] [--without-fire]
//                       [--reference-wavelengths N] [--reference-spp N] [--msaa N]
//                       [--checkpoints N,N,...] [--still-depth-max D]
//
// Each picture's line ends with its frames' summed time (glFinish-bounded, the programs' first
// use included). --depth, --min-weight: the GPU trace's (default 8, 1e-4); --still-frames: how
// many the still pictures average (default 16, the kiosk's); --still-depth D: also the still
// pictures whose frames trace to depth D (the kiosk's picture.still_depth). --cache keeps the
// references (PFM, a few minutes to trace) between runs; default: the build tree. --size draws
// every scene at that size.
// --msaa: the pictures' MSAA samples (default 4, the kiosk's; the frame costs stay at 4).
// --images writes each picture and the reference as PNG. How converged the reference itself
// is: --reference-check N also traces it at N wavelengths, --reference-check-spp N at N
// samples a pixel, and prints how far the usual one is from that. --without-fire: the
// reference at the D line only and the trace without fire, what is left of the trace's own
// error when dispersion is taken out. --reference-wavelengths, --reference-spp: a finer
// reference to measure against (kept apart in the cache, by name).
//
// --checkpoints 16,64,256,...: instead, the kiosk's still view as it accumulates (spectral
// fire, the still frames from --still-depth, deeper to --still-depth-max as the kiosk's
// picture.still_depth_max makes them: gpu/still_schedule.hpp), its ΔE00 printed after each
// count of frames with the frames' summed time and the last frame's depth: the picture against
// the frames a still view is given (docs/accuracy.md, "The still view by time").
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cpu/reference_render.hpp"
#include "cpu/scene_settings.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/frame_composer.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "picture/image_error.hpp"
#include "picture/tone_map.hpp"
#include "scene/scene.hpp"
#include "scene/scene_build.hpp"

#include "bench_frame.hpp"
#include "bench_support.hpp"

namespace {

constexpr const char* kProgram = "bench_still_picture";
template <class T>
T must(gem::Result<T> r) {
    return gem::bench::must(kProgram, std::move(r));
}
gem::gpu::ComposedFrame compose(const gem::gpu::FrameRequest& request,
                                const gem::gpu::RenderTarget& target) {
    return gem::bench::compose(kProgram, request, target);
}
using gem::gpu::TraceDispersion;

struct StillScene {
    const char* name;
    gem::CutShape cut;
    const char* material;
    double elevation_deg;
    double azimuth_deg;
    int size;
};

gem::Scene scene_of(const StillScene& s) {
    gem::Scene scene = gem::default_scene();
    scene.stone.cut = gem::default_cut_params(s.cut);
    scene.material.name = s.material;
    scene.camera.elevation_deg = s.elevation_deg;
    scene.camera.azimuth_deg = s.azimuth_deg;
    scene.width = scene.height = s.size;
    return scene;
}

// The reference at `wavelengths` wavelengths (0: at the D line only, without dispersion) and
// `spp` samples a pixel, traced once and kept in `cache` (colour, and coverage as a second PFM).
gem::Image reference(const StillScene& s, const std::filesystem::path& cache, int wavelengths = 12,
                     int spp = 16) {
    std::string stem = std::string(s.name) + "-" + std::to_string(s.size);
    if (wavelengths == 0) stem += "-d-line";
    if (wavelengths > 0 && wavelengths != 12) stem += "-" + std::to_string(wavelengths) + "nm";
    if (spp != 16) stem += "-" + std::to_string(spp) + "spp";
    const std::filesystem::path colour = cache / (stem + ".pfm");
    const std::filesystem::path coverage = cache / (stem + "-coverage.pfm");
    if (std::filesystem::exists(colour) && std::filesystem::exists(coverage)) {
        gem::Image image = must(gem::read_pfm(colour));
        const gem::Image alpha = must(gem::read_pfm(coverage));
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            image.pixels[i].w = alpha.pixels[i].x;
        }
        return image;
    }
    gem::Scene scene = scene_of(s);
    scene.spectral = wavelengths > 0;
    if (wavelengths > 0) scene.spectral_samples = wavelengths;
    scene.samples_per_pixel = spp;
    scene.depth = 64;
    std::printf("  tracing the reference of %s at %d wavelengths, %d spp ...\n", s.name,
                wavelengths, spp);
    std::fflush(stdout);
    gem::RenderStats stats;
    gem::Image image = must(gem::render_reference(must(gem::build_stone(scene)),
                                                  must(gem::build_environment(scene)),
                                                  gem::render_settings(scene), &stats));
    std::filesystem::create_directories(cache);
    gem::Image alpha = image;
    for (glm::vec4& p : alpha.pixels) p = glm::vec4(p.w, p.w, p.w, 1.0f);
    must(gem::write_pfm(image, colour));
    must(gem::write_pfm(alpha, coverage));
    std::printf("  ... %.0f s\n", stats.seconds);
    return image;
}

struct Variant {
    std::string label;
    TraceDispersion fire;
    int still_frames;     // 1: the moving picture
    int still_depth = 0;  // the still frames' own depth; 0: the moving frames'
};

// The trace of `scene` as gemrender draws it, at `depth` and `min_weight` with `fire`;
// `environment` must outlive it.
gem::gpu::FrameRenderer trace_renderer(const gem::Scene& scene, const gem::Environment& environment,
                                       int depth, double min_weight, TraceDispersion fire) {
    const gem::RenderSettings settings = gem::render_settings(scene);
    gem::gpu::FrameSetup setup;
    setup.method = "trace";
    setup.stone = must(gem::build_stone(scene));
    setup.material = setup.stone.material;
    setup.shading = settings.shading;
    setup.trace = settings.trace;
    setup.trace.max_depth = depth;
    setup.trace.min_weight = min_weight;
    setup.trace_dispersion = fire;
    setup.environment = &environment;
    return must(gem::gpu::FrameRenderer::make(std::move(setup)));
}

// The picture of `s` as the kiosk shows it after `v.still_frames` frames of a still view.
// `ms`: the frames' summed time, each glFinish-bounded.
gem::Image gpu_picture(const StillScene& s, const Variant& v, int depth, double min_weight,
                       int msaa, double* ms) {
    const gem::Scene scene = scene_of(s);
    const gem::Environment environment = must(gem::build_environment(scene));
    auto renderer = trace_renderer(scene, environment, depth, min_weight, v.fire);
    auto target = must(gem::gpu::RenderTarget::make(s.size, s.size));
    const bool spectral = v.fire == TraceDispersion::spectral;
    auto hdr = must(gem::gpu::HdrPicture::make(s.size, s.size,
                                               {.samples = msaa,
                                                .display = {},
                                                .glare = 0.0,
                                                .still_frames = v.still_frames,
                                                .spectral = spectral,
                                                .still_depth = v.still_depth}));
    must(gem::gpu::draw_still_picture(
        renderer, hdr, {.camera = scene.camera, .framing_mm = renderer.stone_radius_mm()}, target,
        ms));
    return target.read();
}

gem::ImageError error_of(gem::Image picture, const gem::Image& reference_display) {
    for (std::size_t i = 0; i < picture.pixels.size(); ++i) {
        picture.pixels[i].w = reference_display.pixels[i].w;
    }
    return must(gem::compare_images(picture, reference_display, {.only_stone = true}));
}

// The kiosk's still view of `s`, drawn frame by frame up to the last checkpoint, compared with
// `reference_display` at each. Its picture holds as many frames as the kiosk's: their count
// sets the strata of the still frames' wavelengths (optics/spectrum.hpp, StillSpectrum), and so
// what the first frames trace.
constexpr int kKioskStillFrames = 1024;  // picture.still_frames (kiosk/settings/kiosk_config.hpp)
void still_view_by_frames(const StillScene& s, const gem::Image& reference_display,
                          const std::vector<int>& checkpoints, int depth, double min_weight,
                          int msaa, int still_depth, int still_depth_max) {
    const gem::Scene scene = scene_of(s);
    const gem::Environment environment = must(gem::build_environment(scene));
    auto renderer =
        trace_renderer(scene, environment, depth, min_weight, TraceDispersion::spectral);
    auto target = must(gem::gpu::RenderTarget::make(s.size, s.size));
    auto hdr = must(gem::gpu::HdrPicture::make(s.size, s.size,
                                               {.samples = msaa,
                                                .display = {},
                                                .glare = 0.0,
                                                .still_frames = kKioskStillFrames,
                                                .spectral = true,
                                                .still_depth = still_depth,
                                                .still_depth_max = still_depth_max}));
    hdr.begin_frame(false);
    double ms = 0.0;
    std::size_t next = 0;
    for (int frame = 1; frame <= checkpoints.back(); ++frame) {
        hdr.begin_frame(true);
        const gem::gpu::FrameStats drawn =
            *compose({.renderer = &renderer,
                      .view = gem::gpu::FrameView{.camera = scene.camera,
                                                  .framing_mm = renderer.stone_radius_mm()},
                      .wait = gem::gpu::FrameWait::frame,
                      .picture = &hdr},
                     target)
                 .stats;
        ms += drawn.cpu_ms;
        if (frame != checkpoints[next]) continue;
        const gem::ImageError e = error_of(target.read(), reference_display);
        std::printf(
            "%-22s still view, %5d frames, the last at depth %2d          ΔE00 %5.2f  "
            "p99 %5.1f  %7.0f ms\n",
            s.name, frame, hdr.still_frame().depth, e.delta_e_mean, e.delta_e_p99, ms);
        std::fflush(stdout);
        ++next;
    }
}

// A still frame with spectral fire against one with exact fire, drawn in turn.
void frame_costs(const StillScene& s, int frames, int depth, double min_weight) {
    const gem::Scene scene = scene_of(s);
    const gem::Environment environment = must(gem::build_environment(scene));
    auto renderer =
        trace_renderer(scene, environment, depth, min_weight, TraceDispersion::spectral);
    auto hdr = must(gem::gpu::HdrPicture::make(
        s.size, s.size,
        {.samples = 4, .display = {}, .glare = 0.0, .still_frames = 16, .spectral = true}));
    auto target = must(gem::gpu::RenderTarget::make(s.size, s.size));
    std::vector<double> spectral, exact, ratio;
    for (int f = -1; f < frames; ++f) {
        double ms[2] = {};
        for (int k = 0; k < 2; ++k) {
            hdr.begin_frame(true);
            if (hdr.settled()) hdr.begin_frame(false);  // a new still view: frames to average
            // A still frame drawn with its wavelengths (spectral) or without (exact fire).
            gem::gpu::StillFrame still = hdr.still_frame();
            if (k == 1) still.wavelengths = nullptr;
            ms[k] = compose({.renderer = &renderer,
                             .view = gem::gpu::FrameView{.camera = scene.camera,
                                                         .framing_mm = renderer.stone_radius_mm()},
                             .wait = gem::gpu::FrameWait::frame,
                             .picture = &hdr,
                             .still = still},
                            target)
                        .stats->cpu_ms;
        }
        if (f < 0) continue;  // the programs' first use
        spectral.push_back(ms[0]);
        exact.push_back(ms[1]);
        ratio.push_back(ms[0] / ms[1]);
    }
    std::printf("%-22s still frame, spectral %7.1f ms, exact %7.1f ms, ratio %.2f (median of %d)\n",
                s.name, gem::bench::median(spectral), gem::bench::median(exact),
                gem::bench::median(ratio), frames);
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 9;
    int depth = 8;
    double min_weight = gem::TraceSettings{}.min_weight;
    std::string cache = GEM_STILL_REFERENCE_CACHE;
    std::string only;
    std::string images;
    int check = 0;
    int check_spp = 0;
    int still_depth = 0;
    bool without_fire = false;
    int size = 0;
    int still_frames = 16;
    int reference_wavelengths = 12;
    int reference_spp = 16;
    int msaa = 4;
    std::vector<int> checkpoints;
    int still_depth_max = 0;
    CLI::App app{"bench_still_picture: the still picture against the spectral reference"};
    app.add_option("--frames", frames, "frames timed per fire")->check(CLI::Range(1, 1000));
    app.add_option("--cache", cache, "references are kept here")->capture_default_str();
    app.add_option("--depth", depth, "depth the GPU traces to")->check(CLI::Range(1, 64));
    app.add_option("--min-weight", min_weight, "branches below this weight are cut")
        ->capture_default_str();
    app.add_option("--only", only, "scenes whose name contains this");
    app.add_option("--images", images, "write the pictures here as PNG");
    app.add_option("--reference-check", check,
                   "also the reference at this many wavelengths against the one at 12")
        ->check(CLI::Range(3, 1000));
    app.add_option("--reference-check-spp", check_spp,
                   "also the reference at this many samples a pixel against the one at 16")
        ->check(CLI::Range(1, 4096));
    app.add_option("--still-depth", still_depth,
                   "also the still pictures whose frames trace to this depth")
        ->check(CLI::Range(1, 64));
    app.add_flag("--without-fire", without_fire,
                 "the reference at the D line only, the trace without fire: the trace's own error");
    app.add_option("--still-frames", still_frames, "frames a still picture averages")
        ->check(CLI::Range(2, 1024))
        ->capture_default_str();
    app.add_option("--size", size, "every scene at this size instead")->check(CLI::Range(16, 4096));
    app.add_option("--reference-wavelengths", reference_wavelengths, "the reference's wavelengths")
        ->check(CLI::Range(3, 1000))
        ->capture_default_str();
    app.add_option("--reference-spp", reference_spp, "the reference's samples a pixel")
        ->check(CLI::Range(1, 4096))
        ->capture_default_str();
    app.add_option("--msaa", msaa, "MSAA samples of the pictures")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    app.add_option("--checkpoints", checkpoints,
                   "the kiosk's still view, compared after each of these counts of frames")
        ->delimiter(',')
        ->check(CLI::Range(1, 1024));
    app.add_option("--still-depth-max", still_depth_max,
                   "with --checkpoints: still frames deeper as they accumulate, to this")
        ->check(CLI::Range(0, 64));
    CLI11_PARSE(app, argc, argv);
    std::sort(checkpoints.begin(), checkpoints.end());
    checkpoints.erase(std::unique(checkpoints.begin(), checkpoints.end()), checkpoints.end());
    auto context = must(gem::gpu::EglContext::headless());
    std::printf("GL: %s\n", context.description().c_str());

    std::vector<StillScene> scenes = {
        {"diamond-40", gem::CutShape::round_brilliant, "diamond", 40.0, 13.7, 384},
        {"diamond-face-up", gem::CutShape::round_brilliant, "diamond", 90.0, 13.7, 384},
        {"oval-sapphire-55", gem::CutShape::oval, "sapphire", 55.0, 0.0, 256},
        {"heart-ruby-65", gem::CutShape::heart, "ruby", 65.0, 0.0, 256},
    };
    if (size > 0) {
        for (StillScene& s : scenes) s.size = size;
    }
    const std::string still = "still: " + std::to_string(still_frames) + " frames, ";
    std::vector<Variant> variants = {
        {"moving: 1 frame, exact fire", TraceDispersion::exact, 1},
        {still + "exact fire", TraceDispersion::exact, still_frames},
        {still + "spectral fire", TraceDispersion::spectral, still_frames},
    };
    if (without_fire) {
        variants = {{"moving: 1 frame, no fire", TraceDispersion::none, 1},
                    {still + "no fire", TraceDispersion::none, still_frames}};
    }
    if (still_depth > 0) {
        const std::string label = ", depth " + std::to_string(still_depth);
        const std::size_t count = variants.size();
        for (std::size_t i = 1; i < count; ++i) {
            Variant v = variants[i];
            v.label += label;
            v.still_depth = still_depth;
            variants.push_back(v);
        }
    }
    const int wavelengths = without_fire ? 0 : reference_wavelengths;
    std::printf(
        "\nAgainst the %s reference (depth 64, %d spp, %s); GPU trace at depth %d, %d× MSAA: "
        "mean / p99 ΔE00 over the stone's pixels\n",
        without_fire ? "D-line" : "spectral", reference_spp,
        without_fire ? "no dispersion" : (std::to_string(wavelengths) + " wavelengths").c_str(),
        depth, msaa);
    for (const StillScene& s : scenes) {
        if (!only.empty() && std::string(s.name).find(only) == std::string::npos) continue;
        const gem::Image ref = gem::to_display(reference(s, cache, wavelengths, reference_spp), {});
        if (check > 0) {
            const gem::Image finer = gem::to_display(reference(s, cache, check, reference_spp), {});
            const gem::ImageError e = must(gem::compare_images(ref, finer, {.only_stone = true}));
            std::printf("%-22s %-36s ΔE00 %5.2f  p99 %5.1f\n", s.name,
                        ("reference, " + std::to_string(wavelengths) + " against " +
                         std::to_string(check) + " wavelengths")
                            .c_str(),
                        e.delta_e_mean, e.delta_e_p99);
        }
        if (check_spp > 0) {
            const gem::Image finer =
                gem::to_display(reference(s, cache, wavelengths, check_spp), {});
            const gem::ImageError e = must(gem::compare_images(ref, finer, {.only_stone = true}));
            std::printf("%-22s %-36s ΔE00 %5.2f  p99 %5.1f\n", s.name,
                        ("reference, " + std::to_string(reference_spp) + " against " +
                         std::to_string(check_spp) + " spp")
                            .c_str(),
                        e.delta_e_mean, e.delta_e_p99);
        }
        if (!images.empty()) {
            std::filesystem::create_directories(images);
            must(gem::write_png(
                ref, std::filesystem::path(images) / (std::string(s.name) + "-reference.png")));
        }
        if (!checkpoints.empty()) {
            still_view_by_frames(s, ref, checkpoints, depth, min_weight, msaa, still_depth,
                                 still_depth_max);
            continue;
        }
        for (std::size_t i = 0; i < variants.size(); ++i) {
            double ms = 0.0;
            const gem::Image picture = gpu_picture(s, variants[i], depth, min_weight, msaa, &ms);
            const gem::ImageError e = error_of(picture, ref);
            std::printf("%-22s %-50s ΔE00 %5.2f  p99 %5.1f  %7.0f ms\n", s.name,
                        variants[i].label.c_str(), e.delta_e_mean, e.delta_e_p99, ms);
            std::fflush(stdout);
            if (!images.empty()) {
                must(gem::write_png(picture,
                                    std::filesystem::path(images) /
                                        (std::string(s.name) + "-" + std::to_string(i) + ".png")));
            }
        }
    }
    if (!checkpoints.empty()) return 0;
    std::printf("\nWhat a still frame costs (trace, depth %d, 4× MSAA)\n", depth);
    for (const StillScene& s : scenes) {
        if (!only.empty() && std::string(s.name).find(only) == std::string::npos) continue;
        frame_costs(s, frames, depth, min_weight);
    }
    return 0;
}
