#include "piece/sight_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "trace/bvh_build.hpp"

namespace gem {
namespace {

struct SightTriangle {
    TriangleCorners corners;
    std::array<glm::dvec3, 3> normals;
    float index = 0.0f;  // a stone's refractive index; 0: the metal's
    glm::dvec3 absorption_per_mm{0.0};
    float size_mm = 0.0f;  // a stone's box's diagonal: no path inside it is longer
};

// Wound so that the corners' cross product agrees with `outward`; false without area (or
// without a place: a corner not finite).
bool wound(SightTriangle& t, const glm::dvec3& outward) {
    const glm::dvec3 n = glm::cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]);
    const double area2 = glm::dot(n, n);
    if (!(area2 > 0.0) || !std::isfinite(area2)) return false;
    if (glm::dot(n, outward) < 0.0) {
        std::swap(t.corners[1], t.corners[2]);
        std::swap(t.normals[1], t.normals[2]);
    }
    return true;
}

void push(std::vector<float>& out, const glm::dvec3& v, float w) {
    out.insert(out.end(),
               {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), w});
}

}  // namespace

SightMesh sight_mesh(const MetalMesh& metal, const std::vector<PlacedStone>& stones) {
    std::vector<SightTriangle> triangles;
    const std::size_t vertices = std::min(metal.positions.size(), metal.normals.size());
    for (std::size_t i = 0; i + 2 < metal.indices.size(); i += 3) {
        SightTriangle t;
        bool placed = true;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = metal.indices[i + static_cast<std::size_t>(k)];
            if (v >= vertices) {  // a corner past the mesh's vertices: no triangle
                placed = false;
                break;
            }
            t.corners[k] = glm::dvec3(metal.positions[v]);
            t.normals[k] = glm::dvec3(metal.normals[v]);
        }
        if (!placed) continue;
        // Outward as its vertex normals say (cpu/piece_tracer.cpp's metal_as_solid).
        if (wound(t, t.normals[0] + t.normals[1] + t.normals[2])) triangles.push_back(t);
    }
    for (const PlacedStone& placed : stones) {
        const Stone& stone = *placed.stone;
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        for (const glm::dvec3& v : stone.vertices) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        const auto size_mm = static_cast<float>(1.01 * glm::length(hi - lo));
        for (const MeshTriangle& tri : stone.triangles) {
            SightTriangle t;
            const glm::dvec3 n =
                placed.placement.direction_to_piece(stone.facets[tri.facet].plane.n);
            for (int k = 0; k < 3; ++k) {
                t.corners[k] = placed.placement.to_piece(stone.vertices[tri.v[k]]);
                t.normals[k] = n;
            }
            t.index = static_cast<float>(placed.material->index());
            t.absorption_per_mm = placed.material->absorption_per_mm;
            t.size_mm = size_mm;
            if (wound(t, n)) triangles.push_back(t);
        }
    }
    std::vector<TriangleCorners> corners;
    corners.reserve(triangles.size());
    for (const SightTriangle& t : triangles) corners.push_back(t.corners);
    // Float boxes on the GPU: padded by a little more than a float's rounding of millimetres.
    const Bvh bvh = build_bvh(corners, 4, kSightMeshDepth, 1e-4);

    std::vector<float> nodes;
    nodes.reserve(8 * bvh.nodes.size());
    for (const BvhNode& node : bvh.nodes) {
        push(nodes, node.lo, static_cast<float>(node.first));
        push(nodes, node.hi, static_cast<float>(node.count));
    }
    std::vector<float> packed;
    packed.reserve(24 * triangles.size());
    for (const std::uint32_t i : bvh.order) {
        const SightTriangle& t = triangles[i];
        push(packed, t.corners[0], t.index);
        push(packed, t.corners[1] - t.corners[0], t.size_mm);
        push(packed, t.corners[2] - t.corners[0], 0.0f);
        for (int k = 0; k < 3; ++k) {
            push(packed, t.normals[k], static_cast<float>(t.absorption_per_mm[k]));
        }
    }
    SightMesh mesh;
    mesh.nodes = std::move(nodes);
    mesh.triangles = std::move(packed);
    mesh.triangle_count = triangles.size();
    return mesh;
}

}  // namespace gem
