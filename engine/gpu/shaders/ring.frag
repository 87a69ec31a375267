// The ring's metal (ring_renderer.hpp): metal.glsl's shading, and in a still view's frames what
// it sees of its own piece (metal_sight.glsl). Everything is in the piece's frame, linear RGB.

in vec3 v_position;
in vec3 v_normal;
layout(location = 0) out vec4 o_colour;
#ifdef VISIBILITY
// A multisampled frame's stones by visibility (frame_renderer.cpp): the samples the metal takes
// from a stone hold no stone, so that the stone's pixel does not weigh the facet it hides there.
layout(location = 1) out uvec2 o_visible;
#endif

uniform vec3 u_eye;             // eye position; a direction toward the eye when at infinity
uniform int u_eye_at_infinity;  // 1: orthographic camera

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;  // a triangle seen from inside (open or badly wound meshes)
    vec3 v = u_eye_at_infinity == 1 ? normalize(u_eye) : normalize(u_eye - v_position);
    vec3 colour = metal_radiance(v_position, n, v);
#ifdef SEES_PIECE
    // The triangle's own plane, toward the eye: where a reflected ray starts off the surface.
    vec3 face = normalize(cross(dFdx(v_position), dFdy(v_position)));
    if (dot(face, v) < 0.0) face = -face;
    colour += piece_correction(v_position, n, face, v);
#endif
    o_colour = vec4(colour, 1.0);
#ifdef VISIBILITY
    o_visible = uvec2(0u);
#endif
}
