#pragma once
// The CPU side of the comparison: reference renders (cpu/reference_render.hpp) of a scene
// with the GPU frame's exact camera, at the full reference settings or cheaper ones; a ring
// scene is traced as a piece (the stone in its metal, render_piece_reference).

#include "picture/image.hpp"
#include "scene/environment.hpp"
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
    Image image;  // alpha: 1 where the (centre) ray hits the stone (or, in a ring scene, metal)
    double seconds = 0.0;
};

Result<CpuFrame> render_cpu(const Scene& scene, const Environment& environment,
                            const glm::dvec3& view, int image, const ReferenceSettings& settings);

// Where the stone alone covers each pixel (1 or 0), whatever is in front of it.
Result<std::vector<float>> stone_coverage(const Scene& scene, const glm::dvec3& view, int image);

}  // namespace gem::accuracy
