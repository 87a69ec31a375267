// The small-stone rows of the accuracy chart (docs/pieces.md): how far the GPU trace of a small
// round brilliant is from the exact reference, by its size on screen and the model it is traced
// with (depth, fire), printed, not asserted. The GPU draws the loose stone at one sample a pixel
// (the pixel's centre) with each model; the CPU reference traces the same centres spectrally
// (12 wavelengths, depth 32), so the error is the model's, not aliasing's (the kiosk averages a
// still view's jittered frames for that). Mean CIEDE2000 over the stone's pixels, averaged over
// three views (elevations 25°, 40° and 60°); the kiosk's budget is a mean of 3
// (gpu/stone_models.hpp), which the kiosk measures GPU against GPU on the piece it shows.
//
//   bench_small_stones [--width-mm W]   (default 1.3: the halo's small diamonds)
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cpu/reference_render.hpp"
#include "geometry/cuts.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/render_target.hpp"
#include "optics/material.hpp"
#include "picture/image_error.hpp"

#include "bench_frame.hpp"
#include "bench_support.hpp"

namespace {

constexpr const char* kProgram = "bench_small_stones";
[[noreturn]] void fail(const std::string& why) {
    gem::bench::fail(kProgram, why);
}
template <class T>
T must(gem::Result<T> r) {
    return gem::bench::must(kProgram, std::move(r));
}

}  // namespace

int main(int argc, char** argv) {
    double width_mm = 1.3;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--width-mm" && i + 1 < argc) {
            width_mm = std::atof(argv[++i]);
        } else {
            fail("usage: bench_small_stones [--width-mm W]");
        }
    }
    auto context = must(gem::gpu::EglContext::headless());
    gem::CutParams cut = gem::default_cut_params(gem::CutShape::round_brilliant);
    cut.width_mm = width_mm;
    const gem::Stone stone = must(gem::make_cut(cut, *gem::find_material("diamond")));
    const gem::Environment environment = gem::Environment::studio();
    const std::vector<gem::Light> lights = {{{-30.0, 80.0, 45.0}, false, {2.0, 2.0, 2.0}}};
    const std::vector<int> sizes = {16, 32, 64, 128, 256};
    const std::vector<double> elevations = {25.0, 40.0, 60.0};
    using gem::gpu::TraceDispersion;
    const std::vector<TraceDispersion> fires = {TraceDispersion::none, TraceDispersion::first_order,
                                                TraceDispersion::exact};
    const std::vector<int> depths = {1, 2, 3, 4, 6, 8};

    gem::gpu::FrameSetup setup;
    setup.method = "trace";
    setup.stone = stone;
    setup.material = stone.material;
    setup.shading.lights = lights;
    setup.environment = &environment;
    setup.cube_face = 256;
    setup.background_colour = glm::vec3(0.0f);
    auto renderer = must(gem::gpu::FrameRenderer::make(std::move(setup)));

    std::printf("%.1f mm round brilliant diamond: mean ΔE00 against the exact reference\n",
                width_mm);
    std::printf("%6s %12s", "px", "fire");
    for (int d : depths) std::printf("  depth %-2d", d);
    std::printf("\n");
    gem::ErrorOptions only_stone;
    only_stone.only_stone = true;
    for (int size : sizes) {
        // [fire][depth] summed over the views
        std::vector<std::vector<double>> error(fires.size(), std::vector<double>(depths.size()));
        auto target = must(gem::gpu::RenderTarget::make(size, size));
        for (double elevation : elevations) {
            gem::RenderSettings settings;
            settings.width = settings.height = size;
            settings.samples_per_pixel = 1;
            settings.camera.elevation_deg = elevation;
            settings.camera.azimuth_deg = 10.0;
            settings.shading.lights = lights;
            settings.trace.max_depth = 32;
            settings.spectral = true;
            settings.background_is_environment = false;
            const gem::Image reference = must(gem::render_reference(stone, environment, settings));
            const gem::gpu::FrameView view{.camera = settings.camera,
                                           .framing_mm = gem::bounding_radius(stone.vertices)};
            for (std::size_t f = 0; f < fires.size(); ++f) {
                for (std::size_t d = 0; d < depths.size(); ++d) {
                    renderer.set_model(0, {depths[d], fires[f]});
                    gem::bench::compose(
                        kProgram,
                        {.renderer = &renderer, .view = view, .wait = gem::gpu::FrameWait::frame},
                        target);
                    // The stone's pixels are the reference's: the GPU's background is opaque.
                    gem::Image drawn = target.read();
                    for (std::size_t i = 0; i < drawn.pixels.size(); ++i) {
                        drawn.pixels[i].w = reference.pixels[i].w;
                    }
                    const auto e = must(gem::compare_images(drawn, reference, only_stone));
                    error[f][d] += e.delta_e_mean / elevations.size();
                }
            }
        }
        for (std::size_t f = 0; f < fires.size(); ++f) {
            std::printf("%6d %12s", size, gem::gpu::to_string(fires[f]));
            for (double e : error[f]) std::printf("  %8.2f", e);
            std::printf("\n");
        }
    }
    return 0;
}
