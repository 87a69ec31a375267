#pragma once
// A stone that is not convex, split by a few planes into convex pieces, so that a ray inside
// it is traced as in a convex stone: the CPU twin of the trace shader's PIECES search
// (trace.frag), beside the triangle BVH (bvh_intersector.cpp) that it is tested against.
//
// Why: the triangle tracer tests every triangle (a heart has 190) for every segment, and a
// triangle costs a few times a plane; a convex piece's exit is the nearest forward plane of
// its own facets, a fifth to a half of the stone's.
//
// How a stone is split: a binary space partition whose cuts are chosen among the stone's
// mirror planes (its symmetry, and the coordinate planes through its centre) and the planes of
// its reflex facets (those with a corner of the stone outside them: the pockets' walls). A
// region of space cuts the stone into a piece whose boundary is the facets' polygons clipped
// to the region and caps on the cuts; the piece is convex exactly when every corner of it lies
// inside every one of those planes (then it lies inside their intersection, and shares its
// whole boundary with it). The split with fewest pieces (at most kMaxPieces) wins; a stone with
// none is not split.
//
// How a ray is traced: the piece holding a point is found down the partition, a point on a
// cut going to the side its direction points to. Inside a piece, the exit is the nearest
// plane ahead, as in a convex stone; a cut crossed is no surface (the same glass on both
// sides): the ray goes on in the piece beyond. A ray leaving a piece through a facet may only
// meet the stone again in another piece: its entry is the nearest of those pieces' entries,
// each by the slab method (convex_intersector.cpp).

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/stone.hpp"

namespace gem {

class ConvexPieces {
  public:
    static constexpr int kMaxPieces = 4;

    // A node of the partition: points with cut.signed_distance(p) <= 0 go below, others
    // above. A child >= 0 is a node, < 0 the piece -1 - child.
    struct Node {
        Plane cut;
        int below = 0;
        int above = 0;
    };

    // One piece: the intersection of its facets' planes and its cuts' half-spaces (cut planes
    // facing out of the piece).
    struct Piece {
        std::vector<std::uint32_t> facets;  // indices into stone.facets
        std::vector<Plane> cuts;
    };

    // The split with fewest pieces; nullopt when the stone is convex (nothing to split) or no
    // split of at most kMaxPieces pieces makes every piece convex.
    static std::optional<ConvexPieces> split(const Stone& stone);

    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<Piece>& pieces() const { return pieces_; }
    // The facets off the stone's convex hull, with a corner outside their plane: a ray leaving
    // through any other leaves the hull there and never meets the stone again.
    const std::vector<std::uint32_t>& pocket_walls() const { return pocket_walls_; }

    // A convex part of a pocket wall: the wall's plane and its edges as planes facing out of
    // it in that plane (a point of the plane is on the polygon when inside every edge). A wall
    // whose loop is convex is one polygon, any other its triangles.
    struct WallPolygon {
        std::uint32_t facet = 0;
        std::vector<Plane> edges;
    };
    // A ray inside the hull (from a pocket wall, out of the stone) can meet the stone only on
    // these: the stone's other facets bound the hull and face out of it.
    const std::vector<WallPolygon>& wall_polygons() const { return wall_polygons_; }

    // The piece holding p, a point of the stone; on a cut (within `on_cut`, mm), the piece its
    // direction d points into.
    int locate(const glm::dvec3& p, const glm::dvec3& d, double on_cut) const;

  private:
    std::vector<Node> nodes_;
    std::vector<Piece> pieces_;
    std::vector<std::uint32_t> pocket_walls_;
    std::vector<WallPolygon> wall_polygons_;
};

}  // namespace gem
