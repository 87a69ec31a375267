#pragma once
// The stone on the GPU, shared by every stone method (docs/design.md, "Only the stone's
// pixels are shaded"): its triangles for the stone pass (stone.vert: position and facet per
// corner), so the rasteriser hands each fragment its entry facet and exact entry point; its
// facet planes and edge neighbours in a uniform block (stone.glsl), read by every shader
// without texture fetches; for convex stones the trace method's first-guess map of exit facets
// by direction (trace/facet_walk.hpp), and for non-convex ones the triangles as a texel array
// for tracing and the obstruction test.

#include <cstdint>

#include "geometry/stone.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/program.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// stone.glsl's uniform block sizes (std140): 256 planes and 3072 edge-neighbour slots take
// 11 KiB of the 16 KiB every OpenGL ES 3.0 GPU offers (GL_MAX_UNIFORM_BLOCK_SIZE).
inline constexpr int kMaxFacets = 256;
inline constexpr int kMaxNeighbours = 3072;
inline constexpr GLuint kStoneBlockBinding = 0;

// The bytes of stone.glsl's block as uploaded (the GL must report the same size for it).
std::size_t stone_block_bytes();

class StoneGeometry {
  public:
    // Errors: more facets or neighbours than the block holds, more triangles than a texture.
    static Result<StoneGeometry> upload(const Stone& stone);

    // Once per program that reads stone.glsl: ties its block to the buffer's binding point.
    void attach(const Program& program) const;
    // Before a draw with `program` in use: the block, and the map or the triangles on
    // texture unit `unit` (u_exit_guess, u_triangles; u_triangle_count).
    void bind(const Program& program, int unit) const;
    // The stone pass: front faces only, depth-tested (GL_LEQUAL, so that a depth pass of the
    // same faces leaves them in) and written, blended over what is drawn (GL_SRC_ALPHA,
    // GL_ONE_MINUS_SRC_ALPHA); restores blending and culling off.
    void draw_front_faces() const;
    // The same faces' depth alone (GL_LESS), colour writes masked off and restored, with the
    // caller's program (stone_depth) in use.
    void draw_depth() const;
    // The same faces' depth (GL_LESS) with the colours the caller's program writes
    // (stone_visibility into the visibility target; the scene's draw buffer none), and
    // `stone_id` into the stencil where they are nearest; leaves the stencil test on.
    void draw_visibility(std::uint32_t stone_id) const;
    // Every triangle with the caller's state (phong's passes).
    void draw_triangles() const;

    bool convex() const { return convex_; }
    int facet_count() const { return facets_; }

  private:
    StoneGeometry() = default;
    // Front faces, depth-tested with `depth_test` and written; restores culling off, GL_LESS.
    void draw_front_triangles(GLenum depth_test) const;
    VertexArray vertex_array_;
    Buffer vertices_;
    Buffer block_;
    Texture exit_guess_;  // convex: usamplerCube of facet indices
    Texture triangles_;   // non-convex: texel array, three corners per triangle
    GLsizei vertex_count_ = 0;
    bool convex_ = true;
    int facets_ = 0;
    int triangle_count_ = 0;
};

}  // namespace gem::gpu
