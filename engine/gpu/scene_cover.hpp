#pragma once
// What a frame's scene covers when everything else is one colour: the piece's rectangle on
// the picture (FrameRenderer::cover()). The picture then draws and finishes only around it
// (hdr_picture.hpp), so a frame costs what the piece covers, not the screen.

#include <glm/vec3.hpp>

#include "gpu/pixel_rect.hpp"

namespace gem::gpu {

struct SceneCover {
    PixelRect rect;        // every pixel the scene may draw into (GL coordinates, y up)
    glm::vec3 background;  // the colour of every other pixel
};

}  // namespace gem::gpu
