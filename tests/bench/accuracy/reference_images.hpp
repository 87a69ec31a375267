#pragma once
// The CPU side of the comparison: reference renders (render/reference_render.hpp) of a scene
// with the GPU frame's exact camera, at the full reference settings or cheaper ones, and for
// a ring scene the environment the stone sees (studio + ring), read back from the GPU's
// virtual cube so the reference shows the ring's reflection as the GPU methods do.

#include "render/environment.hpp"
#include "render/image.hpp"
#include "scenes.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

struct ReferenceSettings {
    int depth = 64;
    double min_weight = 1e-6;
    bool spectral = true;  // 12 wavelengths
    int samples = 1;       // 1: the pixel centre, as the GPU methods sample
};

// The settings of the ground truth every figure is measured against.
inline ReferenceSettings full_reference() {
    return {};
}

struct CpuFrame {
    Image image;  // alpha: 1 where the (centre) ray hits the stone
    double seconds = 0.0;
};

Result<CpuFrame> render_cpu(const Scene& scene, const Environment& environment,
                            const glm::dvec3& view, int image, const ReferenceSettings& settings);

// Studio + the scene's ring as seen from the stone's centre, as an equirectangular
// environment (the GPU's ring cube, read back); the studio itself without a ring. Needs a
// current GL context.
Result<Environment> scene_environment(const Scene& scene, const Environment& studio);

}  // namespace gem::accuracy
