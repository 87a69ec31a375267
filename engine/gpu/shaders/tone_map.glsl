// Scene-linear to display-linear: the GPU twin of engine/picture/tone_map.cpp (the Khronos PBR
// Neutral tone mapper; see there for the reasons and the source of the constants).
uniform float u_exposure;  // 2^exposure_ev
uniform int u_tone_curve;  // 0: clip; 1: neutral

const float kF90 = 0.04;
const float kToneStart = 0.8 - kF90;
const float kDesaturation = 0.15;

vec3 tone_neutral(vec3 c) {
    float x = min(c.r, min(c.g, c.b));
    float f = x <= 2.0 * kF90 ? x - x * x / (4.0 * kF90) : kF90;
    c -= f;
    float peak = max(c.r, max(c.g, c.b));
    if (peak <= kToneStart) return c;
    float new_peak = 1.0 - (1.0 - kToneStart) * (1.0 - kToneStart) / (peak + 1.0 - 2.0 * kToneStart);
    float g = 1.0 / (kDesaturation * (peak - new_peak) + 1.0);
    return c * (new_peak / peak * g) + vec3(new_peak * (1.0 - g));
}

vec3 to_display(vec3 scene_linear) {
    vec3 exposed = max(scene_linear, vec3(0.0)) * u_exposure;
    if (u_tone_curve == 0) return min(exposed, vec3(1.0));
    return clamp(tone_neutral(exposed), 0.0, 1.0);
}
