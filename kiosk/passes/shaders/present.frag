// The kiosk's last pass: copies the picture (what the shopper sees) into the window surface,
// turned to the panel's scanout orientation. The picture holds sRGB bytes; the GBM window
// surface is plain 8-bit (XRGB8888, not sRGB), so the bytes must land as they are.
// PICTURE_BYTES: the sampler hands back the stored bytes (EXT_texture_sRGB_decode's
// SKIP_DECODE_EXT, a sampler state: a lookup through the sampler, not texelFetch, which Mesa
// decodes regardless), point-sampled at the texel's centre, and each is written back exactly
// (b / 255 converts to b). Otherwise the sampler decodes sRGB to linear light and this pass
// encodes it again (IEC 61966-2-1): three powers a pixel, which a CPU rasteriser pays in full.
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
#ifdef PICTURE_BYTES
    vec2 uv = (floor(picture_centre) + 0.5) / vec2(textureSize(u_picture, 0));
    o_colour = vec4(textureLod(u_picture, uv, 0.0).rgb, 1.0);
#else
    vec3 texel = texelFetch(u_picture, ivec2(floor(picture_centre)), 0).rgb;
    o_colour = vec4(srgb_encode(clamp(texel, 0.0, 1.0)), 1.0);
#endif
}
