// Rectangles of the target given as two triangles each (RectDraw, rect_draw.hpp), in normalised
// device coordinates: a pass drawn over some tiles of a picture in one draw. The fragment
// shaders it serves place themselves by gl_FragCoord.
layout(location = 0) in vec2 a_position;

void main() { gl_Position = vec4(a_position, 0.0, 1.0); }
