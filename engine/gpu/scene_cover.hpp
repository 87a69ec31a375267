#pragma once
// What a frame's scene covers when everything else is one colour: the tiles of the picture the
// piece's stones and metal may draw into (FrameRenderer::cover()). The picture then finishes
// only those and what its glare reaches (hdr_picture.hpp), so a frame costs what the piece
// covers, not the screen, nor the rectangle about it.
//
// The tiles come from boxes about the parts, each small on the picture: a box about each stone
// where it sits, and the metal cut into cells, each cell's box about the triangles whose centre
// lies in it. Through the orthographic camera a box's corners bound everything in it.

#include <vector>

#include <glm/vec3.hpp>

#include "gpu/tile_set.hpp"

namespace gem {
class Camera;
struct MetalMesh;
}  // namespace gem

namespace gem::gpu {

struct SceneCover {
    TileSet tiles;         // every pixel the scene may draw into lies in one (GL rows, y up)
    glm::vec3 background;  // the colour of every other pixel
};

struct CoverBox {
    glm::dvec3 lo{0.0}, hi{0.0};
};

// The metal in cubic cells `cell_mm` a side: for each cell holding a triangle's centroid, the
// box about those triangles (whole: a long triangle's box reaches past its cell).
std::vector<CoverBox> metal_cover_boxes(const MetalMesh& mesh, double cell_mm);

// Marks on `tiles` (sized as the camera's picture, cleared first) every tile that the boxes'
// pixels touch through the orthographic `camera`, `margin_px` more each way: a triangle's edge
// rasterises into the pixels it touches, and MSAA's samples sit within them.
void mark_cover(const std::vector<CoverBox>& boxes, const Camera& camera, int margin_px,
                TileSet& tiles);

}  // namespace gem::gpu
