#include "picture/tone_map.hpp"

#include <algorithm>
#include <cmath>

#include "optics/colour.hpp"

namespace gem {

namespace {

// PBR Neutral's constants (KhronosGroup/ToneMapping, PBR_Neutral/README.md).
constexpr double kF90 = 0.04;           // Fresnel at normal incidence of an index-1.5 surface
constexpr double kStart = 0.8 - kF90;   // K_s: highlight compression starts at this peak
constexpr double kDesaturation = 0.15;  // K_d

glm::dvec3 neutral(glm::dvec3 c) {
    const double x = std::min({c.x, c.y, c.z});
    // The darkest channel loses a small offset, smoothly from 0 (so black stays black).
    const double f = x <= 2.0 * kF90 ? x - x * x / (4.0 * kF90) : kF90;
    c -= f;
    const double peak = std::max({c.x, c.y, c.z});
    if (peak <= kStart) return c;
    const double new_peak = 1.0 - (1.0 - kStart) * (1.0 - kStart) / (peak + 1.0 - 2.0 * kStart);
    const double g = 1.0 / (kDesaturation * (peak - new_peak) + 1.0);
    return c * (new_peak / peak * g) + glm::dvec3(new_peak * (1.0 - g));
}

}  // namespace

glm::dvec3 to_display(const glm::dvec3& scene_linear, const DisplayTransform& transform) {
    const glm::dvec3 exposed =
        glm::max(scene_linear, glm::dvec3(0.0)) * std::exp2(transform.exposure_ev);
    switch (transform.curve) {
        case ToneCurve::clip:
            return glm::min(exposed, glm::dvec3(1.0));
        case ToneCurve::neutral:
            return glm::clamp(neutral(exposed), glm::dvec3(0.0), glm::dvec3(1.0));
    }
    return exposed;
}

Image to_display(const Image& scene_linear, const DisplayTransform& transform) {
    Image out = scene_linear;
    for (glm::vec4& p : out.pixels) {
        const glm::dvec3 c = to_display(glm::dvec3(p.x, p.y, p.z), transform);
        p = glm::vec4(glm::vec3(c), p.w);
    }
    return out;
}

double unseen_change(const glm::dvec3& scene_linear, const DisplayTransform& transform) {
    const auto codes = [&](const glm::dvec3& radiance) {
        const glm::dvec3 shown = to_display(radiance, transform);
        return 255.0 * glm::dvec3(srgb_encode(shown.x), srgb_encode(shown.y), srgb_encode(shown.z));
    };
    const glm::dvec3 at = codes(scene_linear);
    const auto unseen = [&](double t) {
        for (int i = 0; i < 27; ++i) {
            const glm::dvec3 step(i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1);
            const glm::dvec3 moved = glm::abs(codes(scene_linear + t * step) - at);
            if (std::max({moved.x, moved.y, moved.z}) >= 0.5) return false;
        }
        return true;
    };
    double lo = 0.0, hi = 1.0;
    while (unseen(hi) && hi < 1e6) {
        lo = hi;
        hi *= 2.0;
    }
    for (int i = 0; i < 48; ++i) {
        const double mid = 0.5 * (lo + hi);
        (unseen(mid) ? lo : hi) = mid;
    }
    return 0.75 * lo;
}

const char* to_string(ToneCurve curve) {
    switch (curve) {
        case ToneCurve::clip:
            return "clip";
        case ToneCurve::neutral:
            return "neutral";
    }
    return "?";
}

std::optional<ToneCurve> tone_curve_named(std::string_view name) {
    if (name == "clip") return ToneCurve::clip;
    if (name == "neutral") return ToneCurve::neutral;
    return std::nullopt;
}

}  // namespace gem
