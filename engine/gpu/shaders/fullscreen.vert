// One triangle covering the viewport, no vertex buffers; v_ndc is the fragment's position
// in normalised device coordinates (-1..1, y up).
out vec2 v_ndc;

void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
    v_ndc = p;
    gl_Position = vec4(p, 0.0, 1.0);
}
