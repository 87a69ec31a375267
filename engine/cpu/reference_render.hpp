#pragma once
// The CPU reference render: every pixel traced exactly (deep ray trees, supersampled,
// optionally spectral), shaded and composited over the background. It is the ground truth
// the table and GPU methods are compared with, and what gemrender draws.

#include <cstdint>

#include "cpu/piece_tracer.hpp"
#include "geometry/stone.hpp"
#include "picture/camera.hpp"
#include "picture/image.hpp"
#include "piece/piece.hpp"
#include "scene/environment.hpp"
#include "scene/shading.hpp"
#include "trace/tracer.hpp"
#include "util/result.hpp"

namespace gem {

struct RenderSettings {
    int width = 512;
    int height = 512;
    int samples_per_pixel = 4;  // stratified over the pixel, deterministic jitter
    CameraSettings camera;
    ShadingSettings shading;
    TraceSettings trace;
    // Dispersion: each wavelength sample is traced with the material's n(λ) and the results
    // summed with the samples' RGB weights. Off: one trace at n(D).
    bool spectral = false;
    int spectral_samples = 12;
    // What shows where the stone is not: the environment seen directly, or a solid colour.
    bool background_is_environment = true;
    glm::dvec3 background_colour{0.0};
};

struct RenderStats {
    std::uint64_t pixel_rays = 0;  // rays handed to the tracer (samples × wavelengths)
    double seconds = 0.0;
};

// RGB: the stone composited over the background; alpha: the share of samples that hit the
// stone (coverage). The material is stone.material. Errors: bad camera or image settings.
Result<Image> render_reference(const Stone& stone, const Environment& environment,
                               const RenderSettings& settings, RenderStats* stats = nullptr);

// The same for a whole piece (cpu/piece_tracer.hpp): every stone, the metal and what passes
// between them; the camera orbits the piece's origin and frames its bounding sphere. `sight`:
// what a ray leaving a part may meet (cpu/piece_tracer.hpp).
Result<Image> render_piece_reference(const Piece& piece, const Environment& environment,
                                     const RenderSettings& settings, RenderStats* stats = nullptr,
                                     PieceSight sight = PieceSight::everything);

}  // namespace gem
