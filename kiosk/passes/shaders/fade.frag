// Lays a held picture over the bound framebuffer with opacity u_alpha: the kiosk's cross-fade
// between presets. The picture is sampled texel for texel (same size as the target), decoded
// from sRGB to linear by the sampler, so blending happens in linear light like every pass.
uniform sampler2D u_picture;
uniform float u_alpha;
out vec4 frag_colour;

void main() {
    frag_colour = vec4(texelFetch(u_picture, ivec2(gl_FragCoord.xy), 0).rgb, u_alpha);
}
