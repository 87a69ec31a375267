#include "gpu/stone_geometry.hpp"

#include <optional>
#include <vector>

#include "geometry/facet_adjacency.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/texel_array.hpp"
#include "trace/facet_walk.hpp"

namespace gem::gpu {
namespace {

// One corner of the stone pass: where it is and which facet its triangle lies on.
struct Corner {
    float position[3];
    std::uint32_t facet;
};

// stone.glsl's block, std140: vec4 planes; a uint per facet (first neighbour slot in bits
// 0-15, edge count in 16-23) four to a uvec4; neighbours as 16-bit indices, eight to a uvec4.
struct StoneBlock {
    float plane[kMaxFacets][4];
    std::uint32_t links[kMaxFacets];
    std::uint32_t neighbours[kMaxNeighbours / 2];
};
static_assert(sizeof(StoneBlock) == 16 * (kMaxFacets + kMaxFacets / 4 + kMaxNeighbours / 8));

}  // namespace

std::size_t stone_block_bytes() {
    return sizeof(StoneBlock);
}

Result<StoneGeometry> StoneGeometry::upload(const Stone& stone) {
    const std::string name = "stone '" + stone.name + "'";
    if (stone.facets.size() > static_cast<std::size_t>(kMaxFacets)) {
        return Error{name + ": " + std::to_string(stone.facets.size()) +
                     " facets, more than the GPU methods hold (" + std::to_string(kMaxFacets) +
                     ")"};
    }
    StoneGeometry g;
    g.convex_ = stone.convex;
    g.facets_ = static_cast<int>(stone.facets.size());

    std::vector<Corner> corners;
    corners.reserve(stone.triangles.size() * 3);
    for (const MeshTriangle& t : stone.triangles) {
        if (t.facet >= stone.facets.size()) {
            return Error{name + " has a triangle on facet " + std::to_string(t.facet) + " of " +
                         std::to_string(stone.facets.size())};
        }
        for (std::uint32_t v : t.v) {
            const glm::vec3 p(stone.vertices[v]);
            corners.push_back({{p.x, p.y, p.z}, t.facet});
        }
    }
    if (corners.empty()) return Error{name + " has no triangles"};
    g.vertex_count_ = static_cast<GLsizei>(corners.size());
    g.vertex_array_ = make_vertex_array();
    glBindVertexArray(g.vertex_array_.get());
    g.vertices_ = make_buffer();
    glBindBuffer(GL_ARRAY_BUFFER, g.vertices_.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(Corner)),
                 corners.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Corner), nullptr);
    glEnableVertexAttribArray(0);
    glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, sizeof(Corner),
                           reinterpret_cast<const void*>(offsetof(Corner, facet)));
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);

    // A convex stone's walk holds the adjacency and the first-guess map; a non-convex one needs
    // only the adjacency.
    std::optional<FacetWalk> walk;
    if (stone.convex) walk.emplace(stone);
    const FacetAdjacency own = walk ? FacetAdjacency{} : facet_adjacency(stone);
    const FacetAdjacency& adjacency = walk ? walk->adjacency() : own;
    StoneBlock block{};
    std::uint32_t slot = 0;
    for (std::size_t f = 0; f < stone.facets.size(); ++f) {
        const Plane& p = stone.facets[f].plane;
        block.plane[f][0] = static_cast<float>(p.n.x);
        block.plane[f][1] = static_cast<float>(p.n.y);
        block.plane[f][2] = static_cast<float>(p.n.z);
        block.plane[f][3] = static_cast<float>(p.d);
        const std::uint32_t count = adjacency.edge_count[f];
        if (slot + count > static_cast<std::uint32_t>(kMaxNeighbours) || count > 255) {
            return Error{name + ": more facet neighbours than the GPU methods hold (" +
                         std::to_string(kMaxNeighbours) + ")"};
        }
        block.links[f] = slot | (count << 16);
        for (std::uint32_t i = 0; i < count; ++i, ++slot) {
            block.neighbours[slot / 2] |= adjacency.edges_of(static_cast<std::uint32_t>(f))[i]
                                          << (16 * (slot % 2));
        }
    }
    g.block_ = make_buffer();
    glBindBuffer(GL_UNIFORM_BUFFER, g.block_.get());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(StoneBlock), &block, GL_STATIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);

    if (walk) {
        const int side = FacetWalk::kGuessSide;
        g.exit_guess_ = make_texture();
        glBindTexture(GL_TEXTURE_CUBE_MAP, g.exit_guess_.get());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
        for (int face = 0; face < 6; ++face) {
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_R16UI, side, side, 0,
                         GL_RED_INTEGER, GL_UNSIGNED_SHORT,
                         walk->guess_map().data() + static_cast<std::size_t>(face) * side * side);
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    } else {
        g.triangle_count_ = static_cast<int>(stone.triangles.size());
        std::vector<float> texels;
        texels.reserve(stone.triangles.size() * 12);
        for (const MeshTriangle& tri : stone.triangles) {
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3& v = stone.vertices[tri.v[k]];
                texels.insert(texels.end(),
                              {static_cast<float>(v.x), static_cast<float>(v.y),
                               static_cast<float>(v.z), static_cast<float>(tri.facet)});
            }
        }
        auto t = upload_texel_array(texels.data(), stone.triangles.size() * 3, "stone triangles");
        if (!t) return Error{t.error()};
        g.triangles_ = std::move(t).value();
    }
    auto ok = gl_check("stone geometry upload");
    if (!ok) return Error{ok.error()};
    return g;
}

void StoneGeometry::attach(const Program& program) const {
    const GLuint index = glGetUniformBlockIndex(program.id(), "StoneFacets");
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(program.id(), index, kStoneBlockBinding);
}

void StoneGeometry::bind_block() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, kStoneBlockBinding, block_.get());
}

void StoneGeometry::bind(const Program& program, int unit) const {
    bind_block();
    if (convex_) return;
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, triangles_.get());
    program.set("u_triangles", unit);
    program.set("u_triangle_count", triangle_count_);
}

void StoneGeometry::bind_exit_guess(const Program& program, int unit) const {
    if (!convex_) return;
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, exit_guess_.get());
    program.set("u_exit_guess", unit);
}

Pipeline StoneGeometry::front_faces(const Program& program) {
    return {&program, Blend::alpha, {true, GL_LEQUAL, true}, Cull::back};
}

Pipeline StoneGeometry::depth_only(const Program& program) {
    Pipeline p{&program, Blend::off, {true, GL_LESS, true}, Cull::back};
    p.colour_write = false;
    return p;
}

Pipeline StoneGeometry::visibility(const Program& program, std::uint32_t stone_id) {
    Pipeline p{&program, Blend::off, {true, GL_LESS, true}, Cull::back};
    p.stencil = {true, GL_ALWAYS, static_cast<GLint>(stone_id), GL_REPLACE};
    return p;
}

void StoneGeometry::draw_triangles() const {
    glBindVertexArray(vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
}

}  // namespace gem::gpu
