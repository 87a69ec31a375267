// The stones' visibility pass (FrameRenderer::render): stone.vert's depth, the stone's number
// into the stencil where it is nearest (StoneGeometry::draw_visibility), and into the
// visibility target the facet each pixel sees, so that the shading pass after the metal draws
// each stone as one rectangle, its pixels in whole blocks, instead of facet by facet
// (trace.frag, VISIBILITY). The scene's colour is not written (its draw buffer is none).
flat in float v_facet_number;
layout(location = 0) out vec4 o_colour;
layout(location = 1) out uint o_facet;

void main() {
    o_colour = vec4(0.0);
    o_facet = uint(v_facet_number);
}
