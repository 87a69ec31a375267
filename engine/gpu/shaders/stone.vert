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
#ifdef VISIBILITY_PASS
// The facet again, as a float (exact to 2^24), for stone_visibility.frag's integer target: the
// integer varying written straight to it came out 0 at every pixel on llvmpipe under QEMU's
// emulated CPU (tcg, -cpu max: the VM test's machine where there is no KVM; reproduced with
// qemu-x86_64 -cpu max, not with -cpu Haswell or the host's own CPU).
flat out float v_facet_number;
#endif

#ifdef VISIBILITY
// The rectangle about the stone in normalised device coordinates (x0, y0, x1, y1): two
// triangles from the vertex index alone, at the near plane (the depth test is off).
uniform vec4 u_quad;

void main() {
    const int kCorner[6] = int[6](0, 1, 2, 2, 1, 3);
    int corner = kCorner[gl_VertexID];
    v_position = vec3(0.0);
    v_facet = 0u;
    gl_Position = vec4((corner & 1) == 0 ? u_quad.x : u_quad.z,
                       (corner & 2) == 0 ? u_quad.y : u_quad.w, -1.0, 1.0);
}
#else
void main() {
    v_position = a_position;
    v_facet = a_facet;
#ifdef VISIBILITY_PASS
    v_facet_number = float(a_facet);
#endif
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
#endif
