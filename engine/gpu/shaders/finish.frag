// The picture's last step from scene radiance to the display: the glare mixed in (an
// energy-conserving mix: the pyramid's mean level holds the picture's energy, spread), then
// exposure and the tone curve (tone_map.glsl). The target is sRGB, so GL encodes the result.
uniform sampler2D u_scene;     // resolved HDR radiance
uniform sampler2D u_glare;     // the pyramid's top level, the sum of u_glare_levels blurs
uniform float u_glare_share;   // 0: no glare
uniform float u_glare_levels;
out vec4 o_colour;

void main() {
    vec3 scene = texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0).rgb;
    if (u_glare_share > 0.0) {
        vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_scene, 0));
        vec3 glare = texture(u_glare, uv).rgb / u_glare_levels;
        scene = mix(scene, glare, u_glare_share);
    }
    o_colour = vec4(to_display(scene), 1.0);
}
