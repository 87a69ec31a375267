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
#include "gpu/pipeline.hpp"
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
    // Before a draw: the block alone (stone.glsl; phong's programs).
    void bind_block() const;
    // The block, and a non-convex stone's triangles on texture unit `unit` (shading.glsl's
    // u_triangles, u_triangle_count), with `program` in use.
    void bind(const Program& program, int unit) const;
    // A convex stone's first-guess map on texture unit `unit` (trace.frag's u_exit_guess).
    void bind_exit_guess(const Program& program, int unit) const;
    // The stone pass's pipelines with the caller's program, front faces only. The shading:
    // depth-tested with GL_LEQUAL (so that a depth pass of the same faces leaves them in) and
    // written, blended over what is drawn.
    static Pipeline front_faces(const Program& program);
    // The same faces' depth alone (GL_LESS), colour writes off (stone_depth).
    static Pipeline depth_only(const Program& program);
    // The same faces' depth (GL_LESS) with the colours the program writes (stone_visibility
    // into the visibility target; the scene's draw buffer none), and `stone_id` into the
    // stencil where they are nearest.
    static Pipeline visibility(const Program& program, std::uint32_t stone_id);
    // Every triangle, with the pipeline in place (its scope unbinds the vertex array).
    void draw_triangles() const;

    bool convex() const { return convex_; }
    int facet_count() const { return facets_; }

  private:
    StoneGeometry() = default;
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
