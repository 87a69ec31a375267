// The multisampled scene resolved over the tiles a frame rewrites (hdr_picture.hpp): each
// pixel the mean of its samples, as glBlitFramebuffer resolves, but drawn over a tile set's
// rectangles in one draw, where a blit each costs llvmpipe about 0.1 ms (bench_pass_floor).
// A multisampled texture is OpenGL ES 3.1's.
uniform highp sampler2DMS u_samples;
uniform int u_sample_count;
out vec4 o_colour;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < u_sample_count; ++i) sum += texelFetch(u_samples, p, i);
    o_colour = sum / float(u_sample_count);
}
