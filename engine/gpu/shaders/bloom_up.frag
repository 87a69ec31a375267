// One step up the glare's pyramid: a 3×3 tent (1 2 1 / 2 4 2 / 1 2 1, over 16) of the smaller
// level's sum, taken bilinear about this texel's centre at ±1 of its texels (Jimenez 2014), added
// to this level's own downsampled picture, so each level's sum carries its own blur plus every
// wider one.
// The tent's nine bilinear taps come from four: along an axis, with the centre at texel b + f
// (texel-centre coordinates, 0 <= f < 1), the taps at -1, 0, +1 weight texels b-1 .. b+2 by
// (1 - f, 2 - f, 1 + f, f) / 4, and each neighbouring pair of those is one bilinear tap at the
// point between them that splits its weight (clamping at an edge repeats the edge texel for
// both forms alike). Same texels, same weights: the sum as nine taps gave it, to rounding.
uniform sampler2D u_source;   // the smaller level's sum
uniform sampler2D u_own;      // this level's downsample
uniform vec2 u_source_texel;  // 1 / the smaller level's size
uniform vec2 u_target_texel;  // 1 / this level's size
out vec4 o_colour;

vec3 tap(float x, float y) { return texture(u_source, (vec2(x, y) + 0.5) * u_source_texel).rgb; }

void main() {
    // This texel's centre in the smaller level's texel-centre coordinates.
    vec2 centre = gl_FragCoord.xy * u_target_texel / u_source_texel - 0.5;
    vec2 b = floor(centre);
    vec2 f = centre - b;
    vec2 w_low = (3.0 - 2.0 * f) * 0.25;                // texels b - 1 and b
    vec2 w_high = 1.0 - w_low;                          // texels b + 1 and b + 2
    vec2 low = b - 1.0 + (2.0 - f) / (3.0 - 2.0 * f);   // where b - 1 and b split w_low
    vec2 high = b + 1.0 + f / (1.0 + 2.0 * f);          // where b + 1 and b + 2 split w_high
    vec3 sum = w_low.y * (w_low.x * tap(low.x, low.y) + w_high.x * tap(high.x, low.y)) +
               w_high.y * (w_low.x * tap(low.x, high.y) + w_high.x * tap(high.x, high.y));
    vec3 own = texelFetch(u_own, ivec2(gl_FragCoord.xy), 0).rgb;
    o_colour = vec4(own + sum, 1.0);
}
