#include "piece/settings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "piece/seat.hpp"
#include "piece/stone_shape.hpp"

namespace gem {

namespace {

constexpr double kPi = 3.14159265358979323846;

constexpr std::array<std::pair<SettingKind, const char*>, 4> kKinds{{
    {SettingKind::solitaire, "solitaire"},
    {SettingKind::halo, "halo"},
    {SettingKind::three_stone, "three-stone"},
    {SettingKind::band, "band"},
}};

Result<bool> check_shank(const ShankParams& s) {
    if (!(s.finger_diameter_mm >= 10.0 && s.finger_diameter_mm <= 30.0)) {
        return Error{"finger_diameter_mm: must be 10..30"};
    }
    if (!(s.width_mm >= 0.8 && s.width_mm <= 12.0)) return Error{"band_width_mm: must be 0.8..12"};
    if (!(s.thickness_mm >= 0.6 && s.thickness_mm <= 5.0)) {
        return Error{"band_thickness_mm: must be 0.6..5"};
    }
    return true;
}

// The shank: a band round the finger (along x) in the yz plane, its top at `top_y`.
double add_shank(const ShankParams& s, double top_y, double width, MetalMesh& metal) {
    const double inner = 0.5 * s.finger_diameter_mm;
    const glm::dvec3 centre(0.0, top_y - inner - s.thickness_mm, 0.0);
    MeshBuilder(metal).torus(centre, {0, 1, 0}, {0, 0, 1}, inner + 0.5 * s.thickness_mm,
                             0.5 * s.thickness_mm, 0.5 * width, 128, 16);
    return centre.y;
}

// The centre stone at the origin in its claws, over a shank. Returns the shank's centre height.
Result<double> set_centre(const SettingParams& p, Piece& piece) {
    piece.stones.push_back({0, {}, "centre"});
    const StoneExtent e = stone_extent(piece.kinds[0]);
    const double shank_top = e.culet_y - kClearanceMm;
    auto claws = add_claws(p.claws, piece.kinds[0], 0, {}, shank_top - 0.25 * p.shank.thickness_mm,
                           piece.metal, piece.holds);
    if (!claws) return Error{claws.error()};
    return add_shank(p.shank, shank_top, p.shank.width_mm, piece.metal);
}

// Claws for a smaller stone: the centre's, scaled to its width (never under 0.4 mm), or fitted
// to it as the centre's are.
ClawParams scaled_claws(const ClawParams& c, double width, double centre_width) {
    ClawParams s = c;
    if (c.width_mm != 0.0) s.width_mm = std::clamp(c.width_mm * width / centre_width, 0.4, 3.0);
    return s;
}

Result<bool> make_three_stone(const SettingParams& p, Piece& piece) {
    auto shank_y = set_centre(p, piece);
    if (!shank_y) return Error{shank_y.error()};
    const StoneExtent c = stone_extent(piece.kinds[0]);
    const StoneExtent s = stone_extent(piece.kinds[1]);
    const ClawParams side = scaled_claws(p.claws, s.girdle_radius, c.girdle_radius);
    // Each side stone stands as high along the band as the centre, its axis through the
    // finger's centre, turned down the band until the girdles are half the two claws' widths
    // and 0.3 mm apart (the claws stand at 45° to the band, so they pass each other); its
    // claws reach down into the shank.
    const glm::dvec3 axis_centre(0.0, shank_y.value(), 0.0);
    const double reach = -shank_y.value();
    const double shank_outer = 0.5 * p.shank.finger_diameter_mm + p.shank.thickness_mm;
    const double apart =
        c.girdle_radius + s.girdle_radius +
        0.5 * (claw_width(p.claws, piece.kinds[0]) + claw_width(side, piece.kinds[1])) + 0.3;
    double lo = 0.0, hi = 0.5 * kPi;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        const glm::dvec3 at = axis_centre + reach * glm::dvec3(0.0, std::cos(mid), std::sin(mid));
        (glm::length(at) < apart ? lo : hi) = mid;
    }
    for (const double sign : {1.0, -1.0}) {
        const glm::dvec3 up(0.0, std::cos(hi), sign * std::sin(hi));
        const Placement place{frame_from_up(up, {1.0, 0.0, 0.0}), axis_centre + reach * up};
        const std::size_t index = piece.stones.size();
        piece.stones.push_back({1, place, sign > 0 ? "side 1" : "side 2"});
        auto claws =
            add_claws(side, piece.kinds[1], index, place,
                      shank_outer - reach - 0.4 * p.shank.thickness_mm, piece.metal, piece.holds);
        if (!claws) return Error{claws.error()};
    }
    return true;
}

Result<bool> make_halo(const SettingParams& p, Piece& piece) {
    auto shank_y = set_centre(p, piece);
    if (!shank_y) return Error{shank_y.error()};
    const StoneExtent c = stone_extent(piece.kinds[0]);
    const StoneExtent s = stone_extent(piece.kinds[1]);
    // The row's inner wall clears the claws' uprights; its tables sit just under the centre's
    // girdle, so the centre stands proud of its halo.
    RowCircle circle;
    const double claw = claw_width(p.claws, piece.kinds[0]);
    circle.radius = c.girdle_radius + claw + 2.0 * kClearanceMm + p.row.wall_mm + s.girdle_radius;
    const double row_y = c.girdle_bottom - 0.1 - s.table_y;
    circle.centre = {0.0, row_y, 0.0};
    auto set = add_bead_row(p.row, circle, 1, "halo", piece);
    if (!set) return Error{set.error()};
    // Four struts carry the halo's floor down to the shank, passing under the centre's pavilion;
    // each hangs from the floor's underside, so its end stays below the small stones' culets.
    const double strut = 0.35 * claw;
    const double floor_bottom = row_y + s.culet_y - kClearanceMm - p.row.wall_mm;
    const double shank_top = c.culet_y - kClearanceMm;
    MeshBuilder b(piece.metal);
    for (int k = 0; k < 4; ++k) {
        const double az = 0.5 * kPi * k;
        const glm::dvec3 out(std::cos(az), 0.0, std::sin(az));
        const glm::dvec3 top = circle.radius * out + glm::dvec3(0.0, floor_bottom - strut, 0.0);
        b.cylinder(top, 0.3 * out + glm::dvec3(0.0, shank_top - 0.3 * p.shank.thickness_mm, 0.0),
                   strut, {0.0, 1.0, 0.0}, 8);
        b.sphere(top, strut, 8, 12);
    }
    return true;
}

Result<bool> make_band(const SettingParams& p, Piece& piece) {
    const StoneExtent s = stone_extent(piece.kinds[0]);
    const double inner = 0.5 * p.shank.finger_diameter_mm;
    // The stones' girdle centres on a circle round the finger, the first on top at the origin;
    // the row's floor stands on a shank as thick as the band asks.
    const double radius = inner + p.shank.thickness_mm + p.row.wall_mm + kClearanceMm - s.culet_y;
    RowCircle circle;
    circle.centre = {0.0, -radius, 0.0};
    circle.e0 = {0.0, 1.0, 0.0};
    circle.e1 = {0.0, 0.0, 1.0};
    circle.radius = radius;
    circle.tables_along_axis = false;
    auto set = add_bead_row(p.row, circle, 0, "band", piece);
    if (!set) return Error{set.error()};
    const double width = 2.0 * (s.girdle_radius + kClearanceMm + p.row.wall_mm);
    MeshBuilder(piece.metal)
        .torus(circle.centre, {0, 1, 0}, {0, 0, 1}, inner + 0.5 * p.shank.thickness_mm,
               0.5 * p.shank.thickness_mm, 0.5 * std::max(width, p.shank.width_mm), 192, 16);
    return true;
}

}  // namespace

std::optional<SettingKind> parse_setting_kind(std::string_view name) {
    for (const auto& [kind, text] : kKinds) {
        if (name == text) return kind;
    }
    return std::nullopt;
}

const char* to_string(SettingKind kind) {
    for (const auto& [k, text] : kKinds) {
        if (k == kind) return text;
    }
    return "?";
}

Result<Piece> make_setting(const SettingParams& params, const std::string& name,
                           std::optional<Stone> centre, std::optional<Stone> small) {
    if (auto ok = check_shank(params.shank); !ok) return Error{ok.error()};
    if (!(params.roughness >= 0.0 && params.roughness <= 1.0)) {
        return Error{"roughness: must be 0..1"};
    }
    const bool wants_centre = params.kind != SettingKind::band;
    const bool wants_small = params.kind != SettingKind::solitaire;
    if (wants_centre && !centre)
        return Error{"centre: a " + std::string(to_string(params.kind)) + " needs a centre stone"};
    if (wants_small && !small)
        return Error{"small: a " + std::string(to_string(params.kind)) + " needs its small stones"};
    if (!wants_centre && centre) return Error{"centre: a band has no centre stone"};
    if (!wants_small && small) return Error{"small: a solitaire has no small stones"};
    Piece piece;
    piece.name = name;
    piece.metal.f0 = metal_f0(params.metal);
    piece.metal.roughness = static_cast<float>(params.roughness);
    if (wants_centre) piece.kinds.push_back(std::move(*centre));
    if (wants_small) piece.kinds.push_back(std::move(*small));
    Result<bool> made = true;
    switch (params.kind) {
        case SettingKind::solitaire: {
            auto shank = set_centre(params, piece);
            if (!shank) made = Error{shank.error()};
            break;
        }
        case SettingKind::halo:
            made = make_halo(params, piece);
            break;
        case SettingKind::three_stone:
            made = make_three_stone(params, piece);
            break;
        case SettingKind::band:
            made = make_band(params, piece);
            break;
    }
    if (!made) return Error{made.error()};
    return piece;
}

}  // namespace gem
