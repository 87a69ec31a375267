#include "piece/bead_row.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "piece/seat.hpp"
#include "piece/stone_shape.hpp"

namespace gem {

namespace {

constexpr double kPi = 3.14159265358979323846;
// How far beyond the girdle a bead's centre stands, as a share of its radius: under
// sin(35°) = 0.57, so that it bears on the crown before it reaches the girdle's edge.
constexpr double kReach = 0.45;

// The row's own frame at angle phi: where its stones' tables face, across the row, along it.
struct RowFrame {
    glm::dvec3 radial, tangent, up, side;
};

RowFrame frame_at(const RowCircle& c, double phi) {
    const glm::dvec3 axis = glm::cross(c.e0, c.e1);
    RowFrame f;
    f.radial = std::cos(phi) * c.e0 + std::sin(phi) * c.e1;
    f.tangent = -std::sin(phi) * c.e0 + std::cos(phi) * c.e1;
    f.up = c.tables_along_axis ? axis : f.radial;
    f.side = c.tables_along_axis ? f.radial : axis;
    return f;
}

// A ring of metal that follows the row, its cross-section an ellipse centred at (y, z) in the
// row's (up, side) coordinates with semi-axes (ay, az).
void add_ring(MeshBuilder& b, const RowCircle& c, double y, double z, double ay, double az,
              int segments) {
    const glm::dvec3 axis = glm::cross(c.e0, c.e1);
    if (c.tables_along_axis) {
        b.torus(c.centre + y * axis, c.e0, c.e1, c.radius + z, az, ay, segments, 12);
    } else {
        b.torus(c.centre + z * axis, c.e0, c.e1, c.radius + y, ay, az, segments, 12);
    }
}

}  // namespace

int stones_that_fit(const BeadRowParams& params, double girdle_radius, double circle_radius) {
    const double half_chord = girdle_radius + 0.5 * params.gap_mm;
    if (!(half_chord < circle_radius)) return 0;
    return static_cast<int>(std::floor(kPi / std::asin(half_chord / circle_radius)));
}

Result<int> add_bead_row(const BeadRowParams& params, const RowCircle& circle, std::size_t kind,
                         const std::string& role, Piece& piece) {
    if (!(params.gap_mm >= 0.05 && params.gap_mm <= 2.0)) return Error{"gap_mm: must be 0.05..2"};
    if (!(params.bead_pct >= 5.0 && params.bead_pct <= 40.0)) {
        return Error{"bead_pct: must be 5..40"};
    }
    if (!(params.wall_mm >= 0.1 && params.wall_mm <= 2.0)) return Error{"wall_mm: must be 0.1..2"};
    const Stone& stone = piece.kinds[kind];
    const StoneExtent e = stone_extent(stone);
    const double rg = e.girdle_radius;
    const int fit = stones_that_fit(params, rg, circle.radius);
    if (fit < 3) {
        return Error{"count: the row's circle is too small for stones " + std::to_string(2.0 * rg) +
                     " mm wide"};
    }
    if (params.count < 0 || params.count > fit) {
        return Error{"count: " + std::to_string(params.count) + " stones do not fit (at most " +
                     std::to_string(fit) + ")"};
    }
    const int n = params.count > 0 ? params.count : fit;
    const std::size_t first = piece.stones.size();
    for (int k = 0; k < n; ++k) {
        const RowFrame f = frame_at(circle, 2.0 * kPi * k / n);
        piece.stones.push_back(
            {kind,
             {frame_from_up(f.up, f.tangent), circle.centre + circle.radius * f.radial},
             role + " " + std::to_string(k + 1)});
    }

    // Walls beside the stones from the floor to the top of the girdle, and the floor under
    // the culets, each clear of the stones.
    MeshBuilder b(piece.metal);
    const double wall = params.wall_mm;
    // As many segments as stones times a whole number, so every stone has the same walls
    // beside it; every wall lies within a girdle's radius and two walls of the row's circle.
    const int segments = circle_segments(circle.radius + rg + 2.0 * wall, n);
    const double floor_top = e.culet_y - kClearanceMm;
    const double wall_bottom = floor_top - wall;
    const double wall_z = rg + kClearanceMm + 0.5 * wall;
    const double wall_y = 0.5 * (wall_bottom + e.girdle_top);
    const double wall_ay = 0.5 * (e.girdle_top - wall_bottom);
    add_ring(b, circle, wall_y, wall_z, wall_ay, 0.5 * wall, segments);
    add_ring(b, circle, wall_y, -wall_z, wall_ay, 0.5 * wall, segments);
    add_ring(b, circle, floor_top - 0.5 * wall, 0.0, 0.5 * wall, wall_z + 0.5 * wall, segments);

    // A bead in each gap on either side, lowered onto the crowns of the two stones beside it
    // (the gap is a mirror plane of the pair, so it bears on both alike), with a stalk out to
    // the wall's top.
    const double bead = 0.01 * params.bead_pct * 2.0 * rg;
    for (int k = 0; k < n; ++k) {
        const RowFrame f = frame_at(circle, 2.0 * kPi * (k + 0.5) / n);
        const glm::dvec3 centre_of_gap = circle.centre + circle.radius * f.radial;
        const PieceStone& left = piece.stones[first + static_cast<std::size_t>(k)];
        // Along the gap, on either side of the point nearest the stone's axis, each bead
        // stands where it is kReach of its radius beyond the girdle, close enough to bear on
        // the crown (whose slope near the girdle is 35 to 42 degrees) and not on the girdle's
        // edge. On a curved row the gap is not the same width across, so this is found in the
        // stone's frame rather than measured from the row's middle.
        const glm::dvec3 gap_in_stone = left.placement.to_stone(centre_of_gap);
        const glm::dvec3 side_in_stone = left.placement.direction_to_stone(f.side);
        const double along = glm::dot(glm::dvec2(gap_in_stone.x, gap_in_stone.z),
                                      glm::dvec2(side_in_stone.x, side_in_stone.z));
        const glm::dvec2 nearest = glm::dvec2(gap_in_stone.x, gap_in_stone.z) -
                                   along * glm::dvec2(side_in_stone.x, side_in_stone.z);
        const double reach = rg + kReach * bead;
        const double half =
            std::sqrt(std::max(reach * reach - glm::dot(nearest, nearest), 0.0625 * rg * rg));
        for (const double sign : {-1.0, 1.0}) {
            const double across = -along + sign * half;
            const glm::dvec3 above =
                centre_of_gap + across * f.side + (e.table_y + 2.0 * bead + 1.0) * f.up;
            const std::optional<glm::dvec3> seated =
                seat_ball(stone, left.placement.to_stone(above),
                          left.placement.direction_to_stone(-f.up), bead);
            if (!seated) {
                return Error{"bead_pct: a bead of " + std::to_string(bead) +
                             " mm does not reach the crowns across a gap of " +
                             std::to_string(params.gap_mm) + " mm"};
            }
            const glm::dvec3 c = left.placement.to_piece(*seated);
            b.sphere(c, bead, 8, 12);
            // The stalk meets the wall a little above its top, so that it passes over the
            // girdles' corners on its way.
            const double stalk = 0.45 * bead;
            const glm::dvec3 wall_top = centre_of_gap +
                                        (across > 0.0 ? 1.0 : -1.0) * wall_z * f.side +
                                        (e.girdle_top + stalk) * f.up;
            b.cylinder(c, wall_top, stalk, f.tangent, 8);
            b.sphere(wall_top, stalk, 6, 8);
            const std::size_t right = first + static_cast<std::size_t>((k + 1) % n);
            piece.holds.push_back({first + static_cast<std::size_t>(k), c, bead});
            piece.holds.push_back({right, c, bead});
        }
    }
    return n;
}

}  // namespace gem
