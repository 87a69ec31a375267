#pragma once
// What the GPU's metal and stones see of their own piece: the piece's sight mesh
// (piece/sight_mesh.hpp) as two RGBA32F textures (texel_array.hpp), which piece_path.glsl walks
// with texelFetch to follow the metal's reflected rays and the stones' exits (SEES_PIECE).

#include "gpu/gl_handles.hpp"
#include "piece/sight_mesh.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class PieceSight {
  public:
    // Errors: more triangles than a texture of the GPU's size limit holds.
    static Result<PieceSight> make(const SightMesh& mesh);

    GLuint nodes() const { return nodes_.get(); }
    GLuint triangles() const { return triangles_.get(); }
    std::size_t triangle_count() const { return triangle_count_; }

  private:
    PieceSight() = default;
    Texture nodes_;
    Texture triangles_;
    std::size_t triangle_count_ = 0;
};

}  // namespace gem::gpu
