#pragma once
// Programs that differ only in which code paths are compiled in. A SIMD rasteriser such as
// llvmpipe runs both sides of a branch on a uniform under a lane mask, so a uniform that picks
// a path costs every path it could pick: the trace shader paid for the first-order fire's
// three environment lookups, the thesis shading's second set of light lobes and the cube at
// infinity's second lookup on every exit, and drew a frame in 1.9 times the time of the
// program holding only its own paths. So each path a draw may skip is a feature, and every
// combination of features a draw asks for is its own program, built the first time it is
// asked for and kept.

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "gpu/program.hpp"
#include "scene/lights.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// Feature bits and the #define each compiles in (the shaders test them with #ifdef).
enum ShaderFeature : std::uint32_t {
    kThesisShading = 1u << 0,   // SHADING_THESIS: the thesis' R/T-factor shading (shading.glsl)
    kCubeAtInfinity = 1u << 1,  // CUBE_AT_INFINITY: the virtual cube infinitely far
    kFireFirstOrder = 1u << 2,  // FIRE_FIRST_ORDER: exit directions moved per channel by d/dn
    kFireExact = 1u << 3,       // FIRE_EXACT: each channel traced at its own index (trace)
    kTwoViews = 1u << 4,        // TWO_VIEWS: a blend of two stored views (table)
    kAbsorbing = 1u << 5,       // ABSORBING: the body absorbs (Beer-Lambert, shading.glsl)
    // SEES_PIECE: a still frame's rays follow the whole piece (piece_path.glsl): the metal's
    // reflections, the stones' exits. Above the light count and the specular power (bit 19).
    kSeesPiece = 1u << 19,
    // VISIBILITY: a stone drawn as the rectangle about it, each pixel's stone and entry facet
    // read from the visibility pass (frame_renderer.hpp): its pixels shaded in whole blocks.
    kVisibility = 1u << 20,
    // VISIBILITY_SAMPLES: with VISIBILITY, the frame is multisampled and the visibility target
    // holds each sample's stone and entry facet (a multisampled integer texture, OpenGL ES 3.1):
    // each facet a pixel's samples show is traced once, weighed by its samples.
    kVisibilitySamples = 1u << 21,
};
// Bits 6-8 hold the number of lights, 0 .. kMaxLights (LIGHT_COUNT n, shading.glsl).
inline constexpr std::uint32_t kLightCountShift = 6;
inline constexpr std::uint32_t kLightCountBits = 7u << kLightCountShift;
constexpr std::uint32_t light_count_feature(int lights) {
    return static_cast<std::uint32_t>(lights) << kLightCountShift;
}
// The light-count feature of a scene's lights (at most kMaxLights are drawn).
inline std::uint32_t light_count_feature(const std::vector<Light>& lights) {
    return light_count_feature(static_cast<int>(std::min<std::size_t>(lights.size(), kMaxLights)));
}
constexpr int light_count_of(std::uint32_t features) {
    return static_cast<int>((features & kLightCountBits) >> kLightCountShift);
}
// Bits 9-18 hold a whole specular exponent h, 1 .. 1023 (SPECULAR_POWER h, specular.glsl);
// 0: any other h, taken by pow at run time.
inline constexpr std::uint32_t kSpecularPowerShift = 9;
inline constexpr int kMaxSpecularPower = 1023;
inline constexpr std::uint32_t kSpecularPowerBits = static_cast<std::uint32_t>(kMaxSpecularPower)
                                                    << kSpecularPowerShift;
std::uint32_t specular_power_feature(double h);
constexpr int specular_power_of(std::uint32_t features) {
    return static_cast<int>((features & kSpecularPowerBits) >> kSpecularPowerShift);
}
static_assert((kSeesPiece & kSpecularPowerBits) == 0 && kSeesPiece > kSpecularPowerBits);
static_assert(kVisibility > kSeesPiece && kVisibilitySamples > kVisibility);
// What shading_features() (frame_uniforms.hpp) may ask of a stone method's program.
inline constexpr std::uint32_t kShadingFeatures = kThesisShading | kCubeAtInfinity | kAbsorbing |
                                                  kLightCountBits | kSpecularPowerBits | kSeesPiece;

// The #defines of `features`, in bit order, then the light count (none for no lights), the
// specular power (none for pow at run time) and SEES_PIECE.
std::vector<std::string> feature_defines(std::uint32_t features);
// The GLSL ES version `features` need: "310 es" for a multisampled integer texture, else "300 es".
std::string glsl_version(std::uint32_t features);

class ProgramVariants {
  public:
    ProgramVariants() = default;
    // `name` is a program of the catalogue (program_catalog.hpp), `defines` added to every
    // variant (e.g. the unrolled exit planes).
    ProgramVariants(std::string name, std::vector<std::string> defines);

    // The variant with exactly `features`; built on the first ask, when `prepare` is called
    // once on it (e.g. to attach a uniform block). Later asks find it without allocating.
    template <class Prepare>
    Result<const Program*> get(std::uint32_t features, Prepare&& prepare) {
        if (auto found = built_.find(features); found != built_.end()) return &found->second;
        auto program = build(features);
        if (!program) return program;
        prepare(*program.value());
        return program;
    }

    // The variant of every light count, 0 .. kMaxLights, built now with `features` (for users
    // whose draws are const and must not build).
    template <class Prepare>
    Result<bool> build_every_light_count(std::uint32_t features, Prepare&& prepare) {
        for (int lights = 0; lights <= kMaxLights; ++lights) {
            auto built = get(features | light_count_feature(lights), prepare);
            if (!built) return Error{built.error()};
        }
        return true;
    }

    // A variant built before, or nullptr (for const users that build every variant up front).
    const Program* find(std::uint32_t features) const {
        const auto found = built_.find(features);
        return found != built_.end() ? &found->second : nullptr;
    }

    const std::string& name() const { return name_; }

  private:
    Result<const Program*> build(std::uint32_t features);

    std::string name_;
    std::vector<std::string> defines_;
    std::map<std::uint32_t, Program> built_;  // node-based: a variant never moves
};

}  // namespace gem::gpu
