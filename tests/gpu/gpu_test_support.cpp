#include "gpu_test_support.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "gpu/gl_handles.hpp"

namespace gem::gpu_test {

Result<gpu::EglContext*> context() {
    static Result<gpu::EglContext> made = gpu::EglContext::headless();
    if (!made) return Error{made.error()};
    return &made.value();
}

double psnr_srgb8(const Image& a, const Image& b, bool only_stone) {
    const std::vector<std::uint8_t> x = to_srgb8(a, 4);
    const std::vector<std::uint8_t> y = to_srgb8(b, 4);
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t p = 0; p + 3 < x.size() && p + 3 < y.size(); p += 4) {
        if (only_stone && x[p + 3] < 128 && y[p + 3] < 128) continue;
        for (int c = 0; c < 3; ++c) {
            const double d = double(x[p + c]) - double(y[p + c]);
            sum += d * d;
        }
        n += 3;
    }
    if (n == 0 || sum == 0.0) return std::numeric_limits<double>::infinity();
    const double mse = sum / static_cast<double>(n);
    return 10.0 * std::log10(255.0 * 255.0 / mse);
}

std::filesystem::path write_artifact(const Image& image, const std::string& name) {
    const std::filesystem::path dir(GEM_ARTIFACT_DIR);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const std::filesystem::path path = dir / (name + ".png");
    (void)write_png(image, path, true);
    return path;
}

Image difference_image(const Image& a, const Image& b, float gain) {
    Image out(a.width, a.height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    if (a.width != b.width || a.height != b.height) return out;
    for (std::size_t p = 0; p < out.pixels.size(); ++p) {
        const glm::vec3 d = glm::abs(glm::vec3(a.pixels[p]) - glm::vec3(b.pixels[p])) * gain;
        out.pixels[p] = glm::vec4(glm::min(d, glm::vec3(1.0f)), 1.0f);
    }
    return out;
}

gpu::FrameSetup trace_setup(const Piece* piece, const Stone* loose,
                            const Environment& environment) {
    gpu::FrameSetup setup;
    setup.method = "trace";
    setup.piece = piece;
    if (loose != nullptr) {
        setup.stone = *loose;
        setup.material = loose->material;
    }
    setup.environment = &environment;
    return setup;
}

Result<Image> mean_of_still_frames(gpu::FrameRenderer& renderer, const Camera& camera, int frames,
                                   const StillSpectrum* spectrum, bool moving) {
    const int w = camera.width(), h = camera.height();
    const gpu::Texture colour = gpu::make_texture_2d(GL_RGBA16F, w, h, GL_NEAREST);
    const gpu::Renderbuffer depth = gpu::make_depth_renderbuffer(w, h);
    const gpu::Framebuffer framebuffer = gpu::make_framebuffer_with(colour.get(), depth.get());
    glViewport(0, 0, w, h);
    Image mean(w, h);
    std::vector<float> frame(4 * static_cast<std::size_t>(w) * h);
    for (int i = 0; i < frames; ++i) {
        gpu::StillFrame still;
        still.index = moving ? -1 : i;
        if (spectrum != nullptr) still.wavelengths = &spectrum->frame(i);
        auto stats = renderer.render(camera, gpu::FrameWait::frame, still);
        if (!stats) return Error{stats.error()};
        glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, frame.data());
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const float* p = &frame[4 * (static_cast<std::size_t>(h - 1 - y) * w + x)];
                mean.at(x, y) += glm::vec4(p[0], p[1], p[2], p[3]) / float(frames);
            }
        }
    }
    return mean;
}

}  // namespace gem::gpu_test
