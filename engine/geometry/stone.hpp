#pragma once
// A stone: a closed polyhedral solid with its facets, triangle mesh, material and symmetry.
// Stone frame (docs/design.md, "Contracts"): y up through the table, culet toward -y, girdle
// in the xz plane, centred on the girdle centre; lengths in millimetres.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "optics/material.hpp"

namespace gem {

// The plane n·x = d, n unit length and pointing out of the solid.
struct Plane {
    glm::dvec3 n{0.0, 1.0, 0.0};
    double d = 0.0;

    double signed_distance(const glm::dvec3& p) const { return glm::dot(n, p) - d; }
};

// What a gemmologist calls the facet; girdle facets are not counted in "57 facets".
enum class FacetKind : std::uint8_t { table, crown, girdle, pavilion, culet, other };

const char* to_string(FacetKind kind);

// Radius of the smallest origin-centred sphere holding all of the given points.
double bounding_radius(const std::vector<glm::dvec3>& vertices);

struct Facet {
    Plane plane;
    std::vector<std::uint32_t> loop;  // vertex indices, counter-clockwise seen from outside
    FacetKind kind = FacetKind::other;
    std::string name;  // tier name, e.g. "star", "upper girdle", or GemCad's tier letter
};

struct MeshTriangle {
    std::array<std::uint32_t, 3> v{};  // counter-clockwise seen from outside
    std::uint32_t facet = 0;
};

struct Stone {
    std::string name;
    std::vector<glm::dvec3> vertices;
    std::vector<Facet> facets;
    std::vector<MeshTriangle> triangles;
    // Convex stones are traced by half-space clipping against facet planes (exact and
    // watertight); non-convex ones against the triangles through a BVH.
    bool convex = true;
    // The stone's point group as orthogonal matrices in the stone frame, identity first.
    std::vector<glm::dmat3> symmetry{glm::dmat3(1.0)};
    Material material;
};

}  // namespace gem
