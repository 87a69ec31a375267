// One more frame of a still view into the running mean: drawn with blending
// GL_CONSTANT_ALPHA / GL_ONE_MINUS_CONSTANT_ALPHA at alpha 1 / (frames so far + 1).
uniform sampler2D u_scene;
out vec4 o_colour;

void main() { o_colour = vec4(texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0).rgb, 1.0); }
