#include "piece/claws.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

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

// The seated tip at distance r from the axis along `out`, lowered from above the table.
std::optional<Tip> tip_at(const Stone& stone, double table_y, const glm::dvec3& out, double r,
                          double radius) {
    const double high = table_y + 2.0 * radius + 1.0;
    const std::optional<glm::dvec3> c =
        seat_ball(stone, glm::dvec3(r * out.x, high, r * out.z), {0.0, -1.0, 0.0}, radius);
    if (!c) return std::nullopt;
    return Tip{*c, c->y + radius};
}

}  // namespace

double claw_width(const ClawParams& params, const Stone& stone) {
    return params.width_mm != 0.0 ? params.width_mm
                                  : std::clamp(0.125 * girdle_width(stone), 0.3, 1.2);
}

Result<bool> add_claws(const ClawParams& params, const Stone& stone, std::size_t index,
                       const Placement& placement, double foot_y, MetalMesh& metal,
                       std::vector<Hold>& holds) {
    if (params.claws < 2 || params.claws > 12) return Error{"claws: must be 2..12"};
    if (params.width_mm != 0.0 && !(params.width_mm >= 0.2 && params.width_mm <= 3.0)) {
        return Error{"claw_width_mm: must be 0.2..3, or 0 to fit the stone"};
    }
    if (!(params.tip_height_pct >= 50.0 && params.tip_height_pct <= 110.0)) {
        return Error{"claw_tip_height_pct: must be 50..110"};
    }
    const StoneExtent e = stone_extent(stone);
    const double target = e.girdle_top + 0.01 * params.tip_height_pct * (e.table_y - e.girdle_top);
    std::vector<glm::dvec3> outs;
    std::vector<double> girdles;
    for (int k = 0; k < params.claws; ++k) {
        const double az = (params.first_deg + 360.0 * k / params.claws) * kPi / 180.0;
        outs.emplace_back(std::cos(az), 0.0, std::sin(az));
        girdles.push_back(outline_radius(stone, outs.back()));
        if (!(girdles.back() > 0.0)) {
            return Error{"claws: the stone '" + stone.name + "' has no girdle"};
        }
    }
    // Whether a tip of this wire reaches the target height somewhere between the girdle and
    // the middle of the crown on every claw's side (further in, the crown and the tip rise).
    auto fits = [&](double wire_width) {
        const double r = kTipToWire * 0.5 * wire_width;
        for (std::size_t k = 0; k < outs.size(); ++k) {
            const std::optional<Tip> inner = tip_at(stone, e.table_y, outs[k], 0.3 * girdles[k], r);
            const std::optional<Tip> outer = tip_at(stone, e.table_y, outs[k], girdles[k], r);
            if (!inner || !outer || inner->top < target || outer->top > target) return false;
        }
        return true;
    };
    // Unless asked for one width, an eighth of the stone's width (0.8 mm on a one-carat round),
    // thinned as a setter would until its tip sits at the height asked on a low crown.
    double w = claw_width(params, stone);
    if (params.width_mm == 0.0) {
        while (!fits(w) && w > 0.3) w = std::max(0.3, 0.85 * w);
    }
    if (!fits(w)) {
        return Error{"claw_tip_height_pct: no place on the crown of '" + stone.name +
                     "' puts a claw tip of " + std::to_string(w) + " mm at that height"};
    }
    const double wire = 0.5 * w;
    const double ball = kTipToWire * wire;
    MeshBuilder b(metal, placement);
    std::vector<glm::dvec3> knees;  // where each claw turns down to its foot

    for (int k = 0; k < params.claws; ++k) {
        const glm::dvec3 out = outs[static_cast<std::size_t>(k)];
        const double girdle = girdles[static_cast<std::size_t>(k)];

        // The tip: moved inward from the girdle until its top stands at the target height
        // (further in, the crown is higher and so is the tip).
        double lo = 0.3 * girdle, hi = girdle;
        for (int i = 0; i < 50; ++i) {
            const double mid = 0.5 * (lo + hi);
            const std::optional<Tip> t = tip_at(stone, e.table_y, out, mid, ball);
            (t && t->top > target ? lo : hi) = mid;
        }
        const Tip tip = *tip_at(stone, e.table_y, out, hi, ball);

        auto at = [&](double r, double y) { return glm::dvec3(r * out.x, y, r * out.z); };
        // The least distance from the axis, at height y, at which a wire clears the stone by
        // `gap` (found by measuring, so that any outline and pavilion are followed).
        auto clear_at = [&](double y, double gap) {
            double in = 0.0, far = girdle + 4.0 * w;
            if (signed_distance(stone, at(in, y)) >= gap) return in;
            for (int i = 0; i < 40; ++i) {
                const double mid = 0.5 * (in + far);
                (signed_distance(stone, at(mid, y)) >= gap ? far : in) = mid;
            }
            return far;
        };

        // The upright beside the girdle: its inner face touches the girdle's band.
        double upright_r = 0.0;
        for (int i = 0; i <= 4; ++i) {
            const double y = e.girdle_bottom + (e.girdle_top - e.girdle_bottom) * i / 4.0;
            upright_r = std::max(upright_r, clear_at(y, wire));
        }
        // From the tip the wire runs outward parallel to the crown where the tip bears on it
        // (the crown beyond lies below that plane: the stone is convex there) to the top of
        // the upright, raised where that would take it into the stone.
        const glm::dvec3 normal = glm::normalize(tip.centre - closest_point(stone, tip.centre));
        const glm::dvec3 along = glm::normalize(out - glm::dot(out, normal) * normal);
        const double s =
            (upright_r - glm::dot(tip.centre, out)) / std::max(glm::dot(along, out), 1e-6);
        glm::dvec3 bend = tip.centre + s * along;
        bend.y = std::max(bend.y, e.girdle_top + wire);
        auto wire_clears = [&](const glm::dvec3& from, const glm::dvec3& to, double skip) {
            for (int i = 1; i <= 32; ++i) {
                const glm::dvec3 p = from + (to - from) * (i / 32.0);
                if (glm::length(p - from) < skip) continue;
                if (signed_distance(stone, p) < wire) return false;
            }
            return true;
        };
        for (int i = 0; i < 40 && !wire_clears(tip.centre, bend, ball); ++i) bend.y += 0.05 * w;

        // Below the girdle the claw runs straight down until the pavilion has drawn back by
        // its clearance, then follows the pavilion, clear of it, down to the culet's depth (a
        // basket), then straight down to its foot.
        const double knee_y = std::max(foot_y, e.culet_y - kClearanceMm - wire);
        double leave_y = e.girdle_bottom;
        while (leave_y > knee_y && clear_at(leave_y, wire + kClearanceMm) > upright_r) {
            leave_y -= 0.05 * w;
        }
        leave_y = std::max(leave_y, knee_y);
        glm::dvec3 previous = at(upright_r, leave_y);
        b.cylinder(previous, bend, wire, -out, 8);
        b.sphere(previous, wire, 8, 12);
        constexpr int kSteps = 4;
        for (int i = 1; i <= kSteps && leave_y > knee_y; ++i) {
            const double y = leave_y + (knee_y - leave_y) * i / kSteps;
            double r = clear_at(y, wire + kClearanceMm);
            // Each point clears the pavilion, but the straight wire between two may cut its
            // bulge (a pointed culet between steps): moved out until the whole wire clears.
            for (int j = 0; j < 40 && !wire_clears(previous, at(r, y), 0.0); ++j) r += 0.02 * w;
            const glm::dvec3 p = at(r, y);
            b.cylinder(p, previous, wire, -out, 8);
            b.sphere(p, wire, 8, 12);
            previous = p;
        }
        if (foot_y < knee_y)
            b.cylinder(at(glm::dot(previous, out), foot_y), previous, wire, -out, 8);
        knees.push_back(previous);
        // The wire ends where its rim meets the tip's ball, so no part of it reaches past the
        // ball toward the stone (the ball alone is seated; wire_clears checks the rest).
        const glm::dvec3 toward = glm::normalize(bend - tip.centre);
        const glm::dvec3 wire_end =
            tip.centre + std::sqrt(std::max(ball * ball - wire * wire, 0.0)) * toward;
        b.cylinder(bend, wire_end, wire, glm::dvec3(0, 1, 0), 8);
        b.sphere(bend, wire, 8, 12);
        b.sphere(tip.centre, ball, 10, 16);
        holds.push_back({index, placement.to_piece(tip.centre), ball});
    }
    // A gallery rail joins the claws under the culet, as in a basket setting.
    for (std::size_t k = 0; k < knees.size(); ++k) {
        b.cylinder(knees[k], knees[(k + 1) % knees.size()], 0.3 * w, glm::dvec3(0, 1, 0), 8);
    }
    return true;
}

}  // namespace gem
