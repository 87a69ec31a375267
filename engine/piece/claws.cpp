#include "piece/claws.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "piece/seat.hpp"
#include "piece/stone_shape.hpp"

namespace gem {

namespace {

constexpr double kPi = 3.14159265358979323846;
// The tip's ball against the wire: a setter rounds the bent end a little wider than the wire.
constexpr double kTipToWire = 1.15;

struct Tip {
    glm::dvec3 centre;
    double top;
};

// The seated tip at distance r from the axis along `out`.
std::optional<Tip> tip_at(const Stone& stone, const glm::dvec3& out, double r, double radius) {
    const double high = stone_extent(stone).table_y + 2.0 * radius + 1.0;
    const std::optional<glm::dvec3> c =
        seat_ball(stone, glm::dvec3(r * out.x, high, r * out.z), {0.0, -1.0, 0.0}, radius);
    if (!c) return std::nullopt;
    return Tip{*c, c->y + radius};
}

}  // namespace

Result<bool> add_claws(const ClawParams& params, const Stone& stone, std::size_t index,
                       const Placement& placement, double foot_y, MetalMesh& metal,
                       std::vector<Hold>& holds) {
    if (params.claws < 2 || params.claws > 12) return Error{"claws: must be 2..12"};
    if (!(params.width_mm >= 0.2 && params.width_mm <= 3.0)) {
        return Error{"claw_width_mm: must be 0.2..3"};
    }
    if (!(params.tip_height_pct >= 50.0 && params.tip_height_pct <= 110.0)) {
        return Error{"claw_tip_height_pct: must be 50..110"};
    }
    const StoneExtent e = stone_extent(stone);
    const double w = params.width_mm;
    const double wire = 0.5 * w;
    const double ball = kTipToWire * wire;
    const double target = e.girdle_top + 0.01 * params.tip_height_pct * (e.table_y - e.girdle_top);
    const double depth = -e.culet_y;
    const double seat_y = -0.35 * depth;  // the gallery rail's height
    MeshBuilder b(metal, placement);
    double rail_radius = 0.0;

    for (int k = 0; k < params.claws; ++k) {
        const double az = (params.first_deg + 360.0 * k / params.claws) * kPi / 180.0;
        const glm::dvec3 out(std::cos(az), 0.0, std::sin(az));
        const double girdle = outline_radius(stone, out);
        if (!(girdle > 0.0)) return Error{"claws: the stone '" + stone.name + "' has no girdle"};

        // The tip: moved inward from the girdle until its top stands at the target height
        // (further in, the crown is higher and so is the tip).
        double lo = 0.3 * girdle, hi = girdle;
        const std::optional<Tip> inner = tip_at(stone, out, lo, ball);
        const std::optional<Tip> outer = tip_at(stone, out, hi, ball);
        if (!inner || !outer || inner->top < target || outer->top > target) {
            return Error{"claw_tip_height_pct: no place on the crown of '" + stone.name +
                         "' puts a claw tip of " + std::to_string(w) + " mm at that height"};
        }
        for (int i = 0; i < 50; ++i) {
            const double mid = 0.5 * (lo + hi);
            const std::optional<Tip> t = tip_at(stone, out, mid, ball);
            (t && t->top > target ? lo : hi) = mid;
        }
        const Tip tip = *tip_at(stone, out, hi, ball);

        // From the tip the wire runs outward parallel to the crown where the tip bears on it
        // (the crown beyond lies below that plane: the stone is convex there), down to the
        // upright outside the girdle.
        const double centre_r = girdle + wire;  // the upright's inner face touches the girdle
        // The crown's normal where the tip bears on it, and the way down the crown from there.
        const glm::dvec3 normal =
            glm::normalize(tip.centre - closest_point(stone, tip.centre));
        const glm::dvec3 along = glm::normalize(out - glm::dot(out, normal) * normal);
        const double radial_now = glm::dot(tip.centre, out);
        const double s = (centre_r - radial_now) / std::max(glm::dot(along, out), 1e-6);
        glm::dvec3 bend = tip.centre + s * along;

        // Below the girdle the upright runs parallel to the pavilion, clear of it, down to the
        // culet's depth (a basket), then straight down to its foot.
        const glm::dvec2 down = glm::normalize(glm::dvec2(-girdle, -depth));
        const glm::dvec2 away(-down.y, down.x);
        const glm::dvec2 start = glm::dvec2(girdle, 0.0) + (wire + kClearanceMm) * away;
        const double joint_y = std::min(start.y + (centre_r - start.x) / down.x * down.y,
                                        e.girdle_bottom);
        const glm::dvec2 knee = start + (std::max(foot_y, e.culet_y) - start.y) / down.y * down;
        const glm::dvec2 rail = start + (seat_y - start.y) / down.y * down;
        rail_radius = std::max(rail_radius, rail.x);
        auto at = [&](double r, double y) { return glm::dvec3(r * out.x, y, r * out.z); };
        const glm::dvec3 joint = at(centre_r, joint_y);
        bend.y = std::max(bend.y, joint.y + w);

        if (foot_y < knee.y) {
            b.cylinder(at(knee.x, foot_y), at(knee.x, knee.y), wire, -out, 8);
            b.sphere(at(knee.x, knee.y), wire, 8, 12);
        }
        b.cylinder(at(knee.x, knee.y), joint, wire, -out, 8);
        b.cylinder(joint, bend, wire, -out, 8);
        b.cylinder(bend, tip.centre, wire, glm::dvec3(0, 1, 0), 8);
        b.sphere(joint, wire, 8, 12);
        b.sphere(bend, wire, 8, 12);
        b.sphere(tip.centre, ball, 10, 16);
        holds.push_back({index, placement.to_piece(tip.centre), ball});
    }
    // A gallery rail joins the claws under the stone, as in a basket setting.
    b.torus(glm::dvec3(0.0, seat_y, 0.0), {1, 0, 0}, {0, 0, -1}, rail_radius, 0.3 * w, 0.3 * w,
            96, 8);
    return true;
}

}  // namespace gem
