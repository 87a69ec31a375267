// One step down the glare's pyramid: the 13-tap filter of Jimenez, "Next Generation Post
// Processing in Call of Duty: Advanced Warfare" (SIGGRAPH 2014): four overlapping 2×2 box
// averages around the centre weighted 0.5 and four corner ones 0.125 each, from bilinear taps
// (each tap averages 2×2 texels), so a texel-sized highlight moves smoothly from level to
// level instead of popping in and out of a coarse texel as the stone turns.
// With u_karis (the first step only) each box is weighted by 1 / (1 + luma), Karis' average,
// so a single sub-pixel sparkle cannot dominate its neighbourhood and flicker as it comes and
// goes.
uniform sampler2D u_source;
uniform vec2 u_source_texel;  // 1 / the source's size
uniform int u_karis;
out vec4 o_colour;

vec3 tap(vec2 uv, vec2 offset) { return texture(u_source, uv + offset * u_source_texel).rgb; }

float karis_weight(vec3 c) {
    return u_karis == 1 ? 1.0 / (1.0 + dot(c, vec3(0.2126, 0.7152, 0.0722))) : 1.0;
}

vec3 box(vec3 a, vec3 b, vec3 c, vec3 d, float share, inout float weight_sum) {
    vec3 mean = 0.25 * (a + b + c + d);
    float w = share * karis_weight(mean);
    weight_sum += w;
    return mean * w;
}

void main() {
    vec2 uv = gl_FragCoord.xy * 2.0 * u_source_texel;  // this texel's centre in the source
    vec3 a = tap(uv, vec2(-2.0, 2.0)), b = tap(uv, vec2(0.0, 2.0)), c = tap(uv, vec2(2.0, 2.0));
    vec3 d = tap(uv, vec2(-2.0, 0.0)), e = tap(uv, vec2(0.0, 0.0)), f = tap(uv, vec2(2.0, 0.0));
    vec3 g = tap(uv, vec2(-2.0, -2.0)), h = tap(uv, vec2(0.0, -2.0)), i = tap(uv, vec2(2.0, -2.0));
    vec3 j = tap(uv, vec2(-1.0, 1.0)), k = tap(uv, vec2(1.0, 1.0));
    vec3 l = tap(uv, vec2(-1.0, -1.0)), m = tap(uv, vec2(1.0, -1.0));
    float weight = 0.0;
    vec3 sum = box(j, k, l, m, 0.5, weight);
    sum += box(a, b, d, e, 0.125, weight);
    sum += box(b, c, e, f, 0.125, weight);
    sum += box(d, e, g, h, 0.125, weight);
    sum += box(e, f, h, i, 0.125, weight);
    o_colour = vec4(sum / weight, 1.0);
}
