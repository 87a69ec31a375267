// The stone pass (stone_geometry.hpp): the stone's own triangles at the current orientation.
// Each fragment gets its entry point on the surface (interpolated in the stone frame, exact on
// a flat facet) and the facet it lies on.
layout(location = 0) in vec3 a_position;
layout(location = 1) in uint a_facet;

uniform mat4 u_view_projection;  // frame_uniforms.hpp: view_projection()

// The depth pass (stone_depth.frag) and the shading pass must place every corner alike, so the
// shading pass's GL_LEQUAL keeps exactly the fragments the depth pass wrote.
invariant gl_Position;

out vec3 v_position;
flat out uint v_facet;

void main() {
    v_position = a_position;
    v_facet = a_facet;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
