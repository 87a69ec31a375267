// The kiosk's last pass: copies the picture (what the shopper sees) into the window surface,
// turned to the panel's scanout orientation. The picture texture is sRGB, so the sampler hands
// back linear light; the GBM window surface is plain 8-bit (XRGB8888, not sRGB), so this pass
// encodes sRGB itself (IEC 61966-2-1) to store the same bytes the picture holds.
// u_from_scanout maps a scanout pixel centre (gl_FragCoord, y up) to the picture texel centre
// it shows: a quarter-turn matrix and an offset in pixels (kiosk/display/rotation.hpp).
uniform sampler2D u_picture;
uniform mat2 u_from_scanout;
uniform vec2 u_from_scanout_offset;
out vec4 o_colour;

vec3 srgb_encode(vec3 linear) {
    vec3 low = linear * 12.92;
    vec3 high = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, vec3(lessThanEqual(linear, vec3(0.0031308))));
}

void main() {
    vec2 picture_centre = u_from_scanout * gl_FragCoord.xy + u_from_scanout_offset;
    vec3 linear = texelFetch(u_picture, ivec2(floor(picture_centre)), 0).rgb;
    o_colour = vec4(srgb_encode(clamp(linear, 0.0, 1.0)), 1.0);
}
