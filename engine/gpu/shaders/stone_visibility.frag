// The stones' visibility pass (FrameRenderer::render): stone.vert's depth, the stone's number
// into the stencil where it is nearest (StoneGeometry::draw_visibility), and into the
// visibility target the facet each pixel sees and the stone's number again, so that the
// shading pass after the metal draws each stone as one rectangle, its pixels in whole blocks,
// instead of facet by facet (trace.frag, VISIBILITY). In a multisampled frame each sample
// holds its own, and the stone's number there says which of a pixel's samples are the stone's
// (its shading pass cannot read the stencil). The scene's colour is not written (its draw
// buffer is none).
flat in float v_facet_number;
uniform uint u_stone;
layout(location = 0) out vec4 o_colour;
layout(location = 1) out uvec2 o_visible;  // facet, stone

void main() {
    o_colour = vec4(0.0);
    o_visible = uvec2(uint(v_facet_number), u_stone);
}
