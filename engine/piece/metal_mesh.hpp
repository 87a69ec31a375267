#pragma once
// The metal of a piece as one triangle mesh with per-vertex normals, in the piece's frame
// (millimetres), and the solids settings are built from. Each solid is closed and may overlap
// the others: a jeweller's solder joint needs no boolean union to look right.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "piece/metal.hpp"
#include "piece/placement.hpp"

namespace gem {

struct MetalMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // unit, outward
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
    glm::vec3 f0{1.0f};                  // normal-incidence reflectance, linear RGB
    float roughness = 0.25f;             // GGX perceptual roughness, 0 (mirror) .. 1
    // Every solid closed and wound as above, so a back face is never seen from outside and
    // the renderer may cull it: what MeshBuilder makes. A model file's mesh (open, or wound
    // either way) is not.
    bool closed = false;

    std::size_t triangle_count() const { return indices.size() / 3; }
    // Radius of the sphere about the origin that holds the metal.
    double radius_mm() const;
};

// How far the chords of the metal's long circles (a halo's or a band's walls) may fall inside
// them: a third of a pixel at the kiosk's closest view. The start view shows a halo's 1.3 mm
// stones 57 px across (44 px/mm) and config/gemkiosk.toml's max_zoom is 3, so 130 px/mm, about
// 0.0077 mm a pixel.
inline constexpr double kChordToleranceMm = 0.0025;

// The farthest a corner of a piece or a ring may lie from its origin, in millimetres, as the
// readers of outside files take them (gltf_piece_frame.hpp, metal_obj.hpp). A ring or a
// necklace reaches a few centimetres; a file reaching further is a scene, or in units the reader
// did not recognise, and a corner past a float's range (3.4e38) poisons the boxes the GPU finds
// the piece's surfaces by (piece/sight_mesh.hpp; fuzz_gltf found a glTF piece whose corners came
// to infinity in millimetres).
inline constexpr double kFarthestCornerMm = 1.0e5;

// The fewest segments, a multiple of `multiple_of`, for a circle of `radius_mm` whose chords
// stay within kChordToleranceMm of it (the sagitta r (1 - cos(pi / n))).
int circle_segments(double radius_mm, int multiple_of = 1);

// Adds solids to a mesh, each made in a local frame that `frame` takes into the mesh's.
class MeshBuilder {
  public:
    // Building on an empty mesh makes it closed (MetalMesh::closed); on one that is not, it
    // stays as it was.
    explicit MeshBuilder(MetalMesh& mesh, Placement frame = {}) : mesh_(mesh), frame_(frame) {
        if (mesh.indices.empty()) mesh.closed = true;
    }

    // A tube of elliptic cross-section swept around a circle: centre `c`, the circle in the
    // plane of e0 and e1 (unit, perpendicular), cross-section semi-axes `radial` (in that
    // plane) and `axial` (along e0 × e1) about the circle of radius `r`.
    void torus(const glm::dvec3& c, const glm::dvec3& e0, const glm::dvec3& e1, double r,
               double radial, double axial, int segments, int profile);
    // A closed cylinder of `sides` from a to c; `e1`, perpendicular to the axis, fixes where
    // the first side vertex lies.
    void cylinder(const glm::dvec3& a, const glm::dvec3& c, double radius, const glm::dvec3& e1,
                  int sides);
    void sphere(const glm::dvec3& c, double radius, int rings, int sides);

  private:
    std::uint32_t vertex(const glm::dvec3& p, const glm::dvec3& n);
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d);

    MetalMesh& mesh_;
    Placement frame_;
};

}  // namespace gem
