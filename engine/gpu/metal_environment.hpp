#pragma once
// What the GPU's metal reflects, made to agree with the CPU reference's metal (one BRDF,
// optics/microfacet.hpp), by the split sum (Karis, "Real Shading in Unreal Engine 4", 2013):
//   - the environment filtered by the metal's GGX lobe: a cube whose every texel is the
//     environment averaged over the lobe about its direction (metal_filter.frag), at a face
//     size that resolves the lobe; a polished metal (roughness under kSmoothRoughness) reads
//     the environment itself, sharp;
//   - the environment BRDF, scale and bias by (n·v, roughness): a small table integrated on
//     the CPU (environment_brdf_table), looked up bilinearly.
// The metal's environment is made once with the frame, since the environment cube does not
// change; the lights, which do, are shaded analytically (metal.glsl).

#include <memory>

#include "gpu/environment_cube.hpp"
#include "gpu/gl_handles.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// Below this roughness the lobe is narrower than the environment cube's texels.
inline constexpr double kSmoothRoughness = 0.05;

class MetalEnvironment {
  public:
    static Result<MetalEnvironment> make(const EnvironmentCube& environment, double roughness);

    // The cube the metal reads along its reflected direction, at level 0.
    const EnvironmentCube& filtered() const { return filtered_ ? *filtered_ : *source_; }
    // The environment itself, unfiltered (what one ray through the piece sees where it leaves:
    // piece_path.glsl).
    const EnvironmentCube& source() const { return *source_; }
    // RG16F, n·v across, roughness down: (scale, bias) of the environment BRDF.
    GLuint brdf_table() const { return brdf_table_.get(); }

  private:
    MetalEnvironment() = default;
    const EnvironmentCube* source_ = nullptr;
    std::unique_ptr<EnvironmentCube> filtered_;  // none: polished, the source itself
    Texture brdf_table_;
};

// The face size that resolves a GGX lobe of `roughness` (four texels across its width at
// least), at most the source's.
int metal_environment_face(double roughness, int source_face);

}  // namespace gem::gpu
