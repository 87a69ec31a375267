#pragma once
// Draws a pass over some rectangles of its target in one draw: two triangles each, for programs
// built with rects.vert. A tile set's rectangles (tile_set.hpp) drawn so cost llvmpipe a few
// microseconds a rectangle, where a scissored draw each costs about twenty
// (bench_pass_floor). Rectangles may overlap where the pass writes what it reads elsewhere (the
// glare's levels), never where it blends.

#include <vector>

#include <glm/vec2.hpp>

#include "gpu/gl_handles.hpp"
#include "gpu/pixel_rect.hpp"

namespace gem::gpu {

class RectDraw {
  public:
    RectDraw();
    // Draws the bound program over `rects`, in the pixels of a target of `size` (its viewport
    // the whole target); the empty ones are skipped. Leaves vertex array 0 bound.
    void draw(const std::vector<PixelRect>& rects, glm::ivec2 size);

  private:
    VertexArray vertex_array_;
    Buffer buffer_;
    std::vector<float> scratch_;  // this draw's vertices, kept between draws
};

}  // namespace gem::gpu
