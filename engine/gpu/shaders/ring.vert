// The ring's mesh in the stone frame; the fragment shader works in that frame too.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_view_projection;  // view_projection() or cube_face_projection()

// The same depth from the depth pass (ring_depth) and the shading pass after it.
invariant gl_Position;

out vec3 v_position;
out vec3 v_normal;

void main() {
    v_position = a_position;
    v_normal = a_normal;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
