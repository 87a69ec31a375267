#pragma once
// The sphere of view directions a database samples (docs/gemdb-format.md, "View grid").
// A view direction points from the stone's centre toward the camera, in the stone frame.
// Views are points of a Fibonacci sphere in the direction range, folded into one fundamental
// domain of the stone's symmetry group and thinned so that no two images come closer than
// 0.9 spacing; a lookup of any direction finds the nearest stored view together with the
// group element that folds the direction onto it.

#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.hpp"

namespace gem {

struct ViewGridSpec {
    // Angular spacing: the square root of the solid angle per view over the whole sphere,
    // so the full sphere holds ceil(4π / spacing²) Fibonacci points.
    double spacing_rad = 0.1;
    // Views whose elevation asin(y) lies below this are not stored (a ring shows the crown).
    double min_elevation_rad = -std::numbers::pi / 2.0;
};

// The camera basis every stored view is traced with: up is the projection of the stone's +y
// onto the image plane, or within kPoleCos of the poles of -z (above) / +z (below);
// right = up × view, so
// (right, up, view) is right-handed and the camera looks along -view.
struct CameraBasis {
    glm::dvec3 view{0.0, 0.0, 1.0};
    glm::dvec3 right{1.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
};
inline constexpr double kPoleCos = 0.999;
CameraBasis canonical_basis(const glm::dvec3& view);

struct ViewMatch {
    std::uint32_t view = 0;      // index of the stored view
    std::uint32_t symmetry = 0;  // index g into ViewGrid::group(): g · asked ≈ stored
    double angle = 0.0;          // radians between g · asked and the stored direction
};

class ViewGrid {
  public:
    // Folds by the elements of `symmetry` that keep the direction range (all of them for the
    // full sphere; those fixing +y otherwise). Errors name the bad spec field or say that the
    // matrices are not an orthogonal group.
    static Result<ViewGrid> build(const ViewGridSpec& spec,
                                  const std::vector<glm::dmat3>& symmetry);
    // Rebuilds a grid from stored parts (the reader); `group_indices` index `symmetry`.
    static Result<ViewGrid> from_parts(const ViewGridSpec& spec,
                                       const std::vector<glm::dmat3>& symmetry,
                                       std::vector<std::uint32_t> group_indices,
                                       const glm::dvec3& key, std::uint32_t sphere_count,
                                       std::vector<std::uint32_t> sphere_indices);

    const ViewGridSpec& spec() const { return spec_; }
    std::size_t size() const { return directions_.size(); }
    const std::vector<glm::dvec3>& directions() const { return directions_; }
    const glm::dvec3& direction(std::uint32_t view) const { return directions_[view]; }
    CameraBasis basis(std::uint32_t view) const { return canonical_basis(directions_[view]); }
    // The folding group (identity first) and where each element sits in the stone's list.
    const std::vector<glm::dmat3>& group() const { return group_; }
    const std::vector<std::uint32_t>& group_indices() const { return group_indices_; }
    // Generic direction whose Voronoi cell among its orbit is the fundamental domain.
    const glm::dvec3& key() const { return key_; }
    std::uint32_t sphere_count() const { return sphere_count_; }  // Fibonacci points, whole sphere
    const std::vector<std::uint32_t>& sphere_indices() const { return sphere_indices_; }

    // Nearest stored view over all symmetric images. Directions below the range are first
    // lifted onto its rim (same azimuth), so they map to rim views.
    ViewMatch nearest(const glm::dvec3& direction) const;
    // The up to out.size() nearest (view, element) pairs, nearest first; returns how many.
    std::size_t nearest_k(const glm::dvec3& direction, std::span<ViewMatch> out) const;

    // Image coordinates (mm from the image centre) in the stored view for a point p of the
    // asked image whose camera has basis (asked_right, asked_up): q = M p. The ray-list at p
    // is g⁻¹ applied to the stored ray-list at q. M is a rotation (roll) or, for mirrors,
    // a reflection; when g · asked misses the stored direction, the small rotation taking
    // one onto the other is included so M stays orthogonal.
    glm::dmat2 image_map(const ViewMatch& match, const glm::dvec3& asked_view,
                         const glm::dvec3& asked_right, const glm::dvec3& asked_up) const;

    // Fibonacci sphere point i of n (y is the polar axis).
    static glm::dvec3 sphere_point(std::uint32_t i, std::uint32_t n);

  private:
    struct Entry {
        glm::dvec3 point;  // h · stored direction
        std::uint32_t view;
        std::uint32_t inverse;  // index of h⁻¹ in group_
    };
    Result<bool> finish(std::vector<std::uint32_t> sphere_indices);
    glm::dvec3 into_range(const glm::dvec3& direction) const;
    std::uint64_t cell_key(const glm::ivec3& cell) const;
    glm::ivec3 cell_of(const glm::dvec3& p) const;

    ViewGridSpec spec_;
    std::vector<glm::dmat3> group_;
    std::vector<std::uint32_t> group_indices_;
    glm::dvec3 key_{1.0, 0.0, 0.0};
    std::uint32_t sphere_count_ = 0;
    std::vector<std::uint32_t> sphere_indices_;
    std::vector<glm::dvec3> directions_;
    // Uniform 3D cell grid over [-1,1]³ holding the entries, sorted by cell key.
    double cell_size_ = 1.0;
    int cells_per_axis_ = 1;
    std::vector<Entry> entries_;
    std::vector<std::uint64_t> cell_keys_;    // occupied cells, ascending
    std::vector<std::uint32_t> cell_starts_;  // entries_[cell_starts_[i] .. cell_starts_[i+1])
};

}  // namespace gem
