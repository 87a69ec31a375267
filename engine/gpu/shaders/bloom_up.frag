// One step up the glare's pyramid: a 3×3 tent (1 2 1 / 2 4 2 / 1 2 1, over 16) of the smaller
// level's sum, added to this level's own downsampled picture (Jimenez 2014), so each level's
// sum carries its own blur plus every wider one.
uniform sampler2D u_source;   // the smaller level's sum
uniform sampler2D u_own;      // this level's downsample
uniform vec2 u_source_texel;  // 1 / the smaller level's size
uniform vec2 u_target_texel;  // 1 / this level's size
out vec4 o_colour;

void main() {
    vec2 uv = gl_FragCoord.xy * u_target_texel;
    vec2 o = u_source_texel;
    vec3 sum = 4.0 * texture(u_source, uv).rgb;
    sum += 2.0 * (texture(u_source, uv + vec2(o.x, 0.0)).rgb + texture(u_source, uv - vec2(o.x, 0.0)).rgb +
                  texture(u_source, uv + vec2(0.0, o.y)).rgb + texture(u_source, uv - vec2(0.0, o.y)).rgb);
    sum += texture(u_source, uv + o).rgb + texture(u_source, uv - o).rgb +
           texture(u_source, uv + vec2(o.x, -o.y)).rgb + texture(u_source, uv + vec2(-o.x, o.y)).rgb;
    vec3 own = texelFetch(u_own, ivec2(gl_FragCoord.xy), 0).rgb;
    o_colour = vec4(own + sum / 16.0, 1.0);
}
