// The stones' depth pass (StoneMethod::draw_depth): stone.vert's depth, colour writes masked
// off, so the metal and the stones after it are shaded only where they are seen.
out vec4 o_colour;

void main() {
    o_colour = vec4(0.0);
}
