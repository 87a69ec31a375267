#pragma once
// Scene-linear radiance to display-linear colour in [0, 1]: an exposure in stops, then a tone
// curve, before the sRGB encoding. The kiosk's finishing pass (engine/gpu/shaders/tone_map.glsl)
// is the GPU twin, so the CPU reference and the GPU methods are compared like for like.
//
// neutral: the Khronos PBR Neutral tone mapper (Khronos Group, 2024; specification in
// KhronosGroup/ToneMapping, PBR_Neutral/README.md). Below a peak of K_s = 0.76 it only lowers
// the darkest channel's small offset (F90 = 0.04), so a stone's body colour is shown as
// rendered; above, the peak channel is compressed toward 1 and the colour is mixed toward white
// at speed K_d = 0.15. Both steps scale and add grey, so the hue of a highlight is kept: a
// per-channel clip (`clip`) turns a bright orange flash yellow and then white.
// clip: the old behaviour, kept for measurements against the linear reference.

#include <optional>
#include <string_view>

#include <glm/vec3.hpp>

#include "picture/image.hpp"

namespace gem {

enum class ToneCurve { clip, neutral };

struct DisplayTransform {
    ToneCurve curve = ToneCurve::neutral;
    double exposure_ev = 0.0;  // the radiance is scaled by 2^exposure_ev first
};

// Negative input is treated as 0; the result lies in [0, 1] per channel.
glm::dvec3 to_display(const glm::dvec3& scene_linear, const DisplayTransform& transform);
// Every pixel's colour; alpha is kept.
Image to_display(const Image& scene_linear, const DisplayTransform& transform);

// The largest change of radiance, up to `t` in every channel at once and either way, that moves
// no channel of `scene_linear`'s 8-bit sRGB output by half a code or more: what the display
// cannot show about that colour (the glare is cut where it adds less, hdr_picture.hpp). Found
// by bisection over the changes of -t, 0 and +t in each channel, with a quarter to spare for
// the curve between those points.
double unseen_change(const glm::dvec3& scene_linear, const DisplayTransform& transform);

const char* to_string(ToneCurve curve);
std::optional<ToneCurve> tone_curve_named(std::string_view name);  // "clip", "neutral"

}  // namespace gem
