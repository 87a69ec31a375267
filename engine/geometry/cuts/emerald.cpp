// The emerald cut: a step cut on a rectangle with cut corners. Every step is a ring of 8
// planes with one tilt, so neighbouring steps meet in horizontal lines and the facets of a
// step meet on the bisectors of the outline's corners; the last pavilion step closes in a
// keel line of length L − W.

#include <array>
#include <cmath>
#include <string>

#include "geometry/cuts/cut_internal.hpp"

namespace gem::cuts {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Corner cut: each leg a fifth of the width or so, as on typical emerald cuts; 0.22 W keeps
// the corner facets of the last pavilion step (which shrink by 0.83 per unit inset) alive.
constexpr double kCornerLeg = 0.22;
// Crown steps get flatter toward the table, pavilion steps toward the keel; the middle step
// has the nominal angle.
constexpr std::array<double, 3> kCrownStepOffsetDeg{5.0, 0.0, -5.0};
constexpr std::array<double, 3> kPavilionStepOffsetDeg{8.0, 0.0, -8.0};

struct Side {
    glm::dvec2 n;     // outward unit normal in (x, z)
    double distance;  // of the side's line from the centre
};

std::array<Side, 8> octagon(double length, double width) {
    const double a = length / 2.0, b = width / 2.0, c = kCornerLeg * width;
    const double s = 1.0 / std::sqrt(2.0);
    const double bevel = (a + b - c) * s;
    return {{{{1, 0}, a},
             {{s, s}, bevel},
             {{0, 1}, b},
             {{-s, s}, bevel},
             {{-1, 0}, a},
             {{-s, -s}, bevel},
             {{0, -1}, b},
             {{s, -s}, bevel}}};
}

// The plane of tilt `angle` (radians) over side `side` starting at inset `inset`, height `y`;
// `up` is +1 for the crown and −1 for the pavilion.
Plane step_plane(const Side& side, double angle, double inset, double y, double up) {
    const glm::dvec3 n(std::sin(angle) * side.n.x, up * std::cos(angle),
                       std::sin(angle) * side.n.y);
    return {n, std::sin(angle) * (side.distance - inset) + up * std::cos(angle) * y};
}

}  // namespace

Result<Stone> make_emerald(const CutParams& params) {
    const double w = params.width_mm;
    const double g = params.girdle_pct / 100.0 * w;
    const std::array<Side, 8> sides = octagon(params.length_to_width * w, w);
    std::vector<FacetPlane> planes;

    const double crown_run = (1.0 - params.table_pct / 100.0) * w / 2.0 / 3.0;
    double y = g / 2.0;
    std::vector<FacetPlane> crown;
    for (int i = 0; i < 3; ++i) {
        const double angle = (params.crown_angle_deg + kCrownStepOffsetDeg[i]) * kPi / 180.0;
        for (const Side& side : sides) {
            crown.push_back({step_plane(side, angle, i * crown_run, y, 1.0), FacetKind::crown,
                             "crown step " + std::to_string(i + 1)});
        }
        y += crown_run * std::tan(angle);
    }
    planes.push_back({Plane{{0.0, 1.0, 0.0}, y}, FacetKind::table, "table"});
    planes.insert(planes.end(), crown.begin(), crown.end());

    const double pavilion_run = w / 2.0 / 3.0;
    y = -g / 2.0;
    for (int i = 0; i < 3; ++i) {
        const double angle = (params.pavilion_angle_deg + kPavilionStepOffsetDeg[i]) * kPi / 180.0;
        for (const Side& side : sides) {
            planes.push_back({step_plane(side, angle, i * pavilion_run, y, -1.0),
                              FacetKind::pavilion, "pavilion step " + std::to_string(i + 1)});
        }
        y -= pavilion_run * std::tan(angle);
    }
    for (const Side& side : sides) {
        const glm::dvec3 n(side.n.x, 0.0, side.n.y);
        planes.push_back({Plane{n, side.distance}, FacetKind::girdle, "girdle"});
    }
    return stone_from_planes(planes, "emerald");
}

}  // namespace gem::cuts
