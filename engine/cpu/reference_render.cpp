#include "cpu/reference_render.hpp"

#include <atomic>
#include <chrono>
#include <cmath>

#include "cpu/piece_tracer.hpp"
#include "optics/spectrum.hpp"
#include "trace/parallel.hpp"

namespace gem {

namespace {

// A deterministic hash to [0, 1) (a 32-bit integer mix in the style of Wellons' "lowbias32"),
// so stratified jitter is the same on every run and every thread count.
double hash01(std::uint32_t x, std::uint32_t y, std::uint32_t s) {
    std::uint32_t h = x * 0x9E3779B9u ^ (y + 0x7F4A7C15u) * 0x85EBCA6Bu ^ (s + 1u) * 0xC2B2AE35u;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return (h >> 8) * (1.0 / 16777216.0);
}

// Sample s of n inside the unit pixel, jittered inside its stratum: a cols × rows grid when
// n is such a product, otherwise n vertical strips, so the strata always tile the pixel and
// every part of it is sampled equally. A single sample sits at the pixel centre.
glm::dvec2 sample_offset(int x, int y, int s, int n) {
    if (n == 1) return {0.5, 0.5};
    int cols = static_cast<int>(std::round(std::sqrt(static_cast<double>(n))));
    if (cols * (n / cols) != n) cols = n;
    const int rows = n / cols;
    const int cx = s % cols;
    const int cy = s / cols;
    const auto ux = static_cast<std::uint32_t>(x);
    const auto uy = static_cast<std::uint32_t>(y);
    const auto us = static_cast<std::uint32_t>(2 * s);
    return {(cx + hash01(ux, uy, us)) / cols, (cy + hash01(ux, uy, us + 1)) / rows};
}

struct Wavelength {
    std::vector<double> iors;  // one for each material traced
    glm::dvec3 weight;
};

// The pixel loop both references share: stratified samples per pixel, each traced at every
// wavelength by `sample(ray, wavelength index, x, y, sample index, scratch, colour&)`, which
// says whether the ray met what is drawn (coverage); a miss shows the background.
template <class Scratch, class Sample>
Image render_pixels(const Camera& camera, const Environment& environment,
                    const RenderSettings& settings, const std::vector<Wavelength>& wavelengths,
                    const Sample& sample, std::atomic<std::uint64_t>& rays) {
    Image image(settings.width, settings.height);
    const int spp = settings.samples_per_pixel;
    parallel_for(
        static_cast<std::size_t>(settings.height), [&](std::size_t begin, std::size_t end) {
            Scratch scratch;  // reused for every sample of these rows
            std::uint64_t traced = 0;
            for (auto y = static_cast<int>(begin); y < static_cast<int>(end); ++y) {
                for (int x = 0; x < settings.width; ++x) {
                    glm::dvec3 sum(0.0);
                    int hits = 0;
                    for (int s = 0; s < spp; ++s) {
                        const glm::dvec2 o = sample_offset(x, y, s, spp);
                        const Ray ray = camera.ray(x + o.x, y + o.y);
                        glm::dvec3 colour(0.0);
                        bool hit = false;
                        for (std::size_t w = 0; w < wavelengths.size(); ++w) {
                            ++traced;
                            glm::dvec3 c(0.0);
                            // A miss at one wavelength is a miss at all: the silhouette does
                            // not depend on the index.
                            if (!sample(ray, w, x, y, s, scratch, c)) break;
                            hit = true;
                            colour += wavelengths[w].weight * c;
                        }
                        if (hit) {
                            ++hits;
                            sum += colour;
                        } else {
                            sum += settings.background_is_environment
                                       ? environment.radiance(ray.direction)
                                       : settings.background_colour;
                        }
                    }
                    image.at(x, y) = glm::vec4(glm::vec3(sum / static_cast<double>(spp)),
                                               static_cast<float>(hits) / static_cast<float>(spp));
                }
            }
            rays += traced;
        });
    return image;
}

// Checks the settings and lists the wavelengths to trace at: n(λ) per sample, or n(D) once.
Result<std::vector<Wavelength>> wavelengths_for(const RenderSettings& settings,
                                                const std::vector<const Material*>& materials) {
    if (settings.samples_per_pixel < 1) return Error{"samples per pixel: must be at least 1"};
    if (settings.shading.lights.size() > static_cast<std::size_t>(kMaxLights)) {
        return Error{"lights: at most " + std::to_string(kMaxLights) + " are allowed"};
    }
    std::vector<Wavelength> out;
    if (settings.spectral) {
        if (settings.spectral_samples < 1) return Error{"spectral samples: must be at least 1"};
        for (const SpectralSample& s : spectral_samples(settings.spectral_samples)) {
            Wavelength w{{}, s.rgb_weight};
            for (const Material* m : materials) w.iors.push_back(m->index(s.wavelength_nm));
            out.push_back(std::move(w));
        }
    } else {
        Wavelength w{{}, glm::dvec3(1.0)};
        for (const Material* m : materials) w.iors.push_back(m->index());
        out.push_back(std::move(w));
    }
    return out;
}

void record(RenderStats* stats, std::uint64_t rays, std::chrono::steady_clock::time_point start) {
    if (stats == nullptr) return;
    stats->pixel_rays = rays;
    stats->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Result<Image> render_reference(const Stone& stone, const Environment& environment,
                               const RenderSettings& settings, RenderStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    auto wavelengths = wavelengths_for(settings, {&stone.material});
    if (!wavelengths) return Error{wavelengths.error()};
    Result<Camera> camera = Camera::make(settings.camera, bounding_radius(stone.vertices),
                                         settings.width, settings.height);
    if (!camera) return Error{camera.error()};
    const Tracer tracer(stone);
    const Shader shader(stone, stone.material, environment, settings.shading);
    std::atomic<std::uint64_t> rays{0};
    const auto& ws = wavelengths.value();
    Image image = render_pixels<RayList>(
        camera.value(), environment, settings, ws,
        [&](const Ray& ray, std::size_t w, int, int, int, RayList& list, glm::dvec3& colour) {
            tracer.trace(ray, ws[w].iors[0], settings.trace, list);
            if (!list.hit) return false;
            colour = shader.shade(list);
            return true;
        },
        rays);
    record(stats, rays.load(), start);
    return image;
}

Result<Image> render_piece_reference(const Piece& piece, const Environment& environment,
                                     const RenderSettings& settings, RenderStats* stats,
                                     PieceSight sight) {
    const auto start = std::chrono::steady_clock::now();
    if (settings.shading.model != ShadingModel::physical) {
        return Error{"a piece is shaded physically (the thesis' model is for one stone)"};
    }
    std::vector<const Material*> materials;
    for (const Stone& kind : piece.kinds) materials.push_back(&kind.material);
    auto wavelengths = wavelengths_for(settings, materials);
    if (!wavelengths) return Error{wavelengths.error()};
    Result<Camera> camera =
        Camera::make(settings.camera, piece.radius_mm(), settings.width, settings.height);
    if (!camera) return Error{camera.error()};
    const PieceTracer tracer(piece, environment, settings.shading, settings.trace, sight);
    std::atomic<std::uint64_t> rays{0};
    const auto& ws = wavelengths.value();
    Image image = render_pixels<PieceTracer::Scratch>(
        camera.value(), environment, settings, ws,
        [&](const Ray& ray, std::size_t w, int x, int y, int s, PieceTracer::Scratch& scratch,
            glm::dvec3& colour) {
            // Rough metal is sampled: one stream a pixel sample, the same on every run.
            scratch.random = (static_cast<std::uint64_t>(y) << 40) ^
                             (static_cast<std::uint64_t>(x) << 16) ^ static_cast<std::uint64_t>(s);
            bool hit = false;
            colour = tracer.radiance(ray, ws[w].iors, scratch, &hit);
            return hit;
        },
        rays);
    record(stats, rays.load(), start);
    return image;
}

}  // namespace gem
