#include "render/reference_render.hpp"

#include <atomic>
#include <chrono>
#include <cmath>

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
    double ior;
    glm::dvec3 weight;
};

}  // namespace

Result<Image> render_reference(const Stone& stone, const Environment& environment,
                               const RenderSettings& settings, RenderStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    if (settings.samples_per_pixel < 1) return Error{"samples per pixel: must be at least 1"};
    if (settings.shading.lights.size() > static_cast<std::size_t>(kMaxLights)) {
        return Error{"lights: at most " + std::to_string(kMaxLights) + " are allowed"};
    }
    Result<Camera> camera_result = Camera::make(settings.camera, bounding_radius(stone.vertices),
                                                settings.width, settings.height);
    if (!camera_result) return Error{camera_result.error()};
    const Camera& camera = camera_result.value();

    std::vector<Wavelength> wavelengths;
    if (settings.spectral) {
        if (settings.spectral_samples < 1) return Error{"spectral samples: must be at least 1"};
        for (const SpectralSample& s : spectral_samples(settings.spectral_samples)) {
            wavelengths.push_back({stone.material.index(s.wavelength_nm), s.rgb_weight});
        }
    } else {
        wavelengths.push_back({stone.material.index(), glm::dvec3(1.0)});
    }

    const Tracer tracer(stone);
    const Shader shader(stone, stone.material, environment, settings.shading);
    Image image(settings.width, settings.height);
    const int spp = settings.samples_per_pixel;
    std::atomic<std::uint64_t> rays{0};
    parallel_for(
        static_cast<std::size_t>(settings.height), [&](std::size_t begin, std::size_t end) {
            RayList list;  // reused for every sample of these rows
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
                        for (const Wavelength& w : wavelengths) {
                            tracer.trace(ray, w.ior, settings.trace, list);
                            ++traced;
                            if (!list.hit) break;  // the silhouette does not depend on n
                            hit = true;
                            colour += w.weight * shader.shade(list);
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
    if (stats != nullptr) {
        stats->pixel_rays = rays.load();
        stats->seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return image;
}

}  // namespace gem
