#pragma once
// Parametric settings: the pieces a shop sells most, made to fit their stones. The claws' tips
// stand at 90 to 100 % of the crown's height, as GIA's benchmark asks (claws.hpp); the other
// proportions are defaults chosen here and set per piece: a claw an eighth of the stone's
// width, small stones 0.15 mm apart with beads a fifth of their width, and a ring size given
// as the finger's diameter (17.3 mm is US size 7; ISO 8653 sizes a ring by its inner
// circumference, here 54.4 mm).

#include <optional>
#include <string>

#include "geometry/stone.hpp"
#include "piece/bead_row.hpp"
#include "piece/claws.hpp"
#include "piece/metal.hpp"
#include "piece/piece.hpp"
#include "util/result.hpp"

namespace gem {

enum class SettingKind {
    solitaire,    // one stone in claws
    halo,         // the centre in claws, ringed by a row of small stones
    three_stone,  // the centre in claws between two side stones in claws
    band,         // small stones all the way round (an eternity band); no centre stone
};
std::optional<SettingKind> parse_setting_kind(std::string_view name);
const char* to_string(SettingKind kind);

struct ShankParams {
    double finger_diameter_mm = 17.3;
    double width_mm = 2.0;      // along the finger
    double thickness_mm = 1.6;  // radially
};

struct SettingParams {
    SettingKind kind = SettingKind::solitaire;
    Metal metal = Metal::yellow_gold;
    double roughness = 0.25;
    ShankParams shank;
    ClawParams claws;   // the centre stone's; side stones' claws are scaled to their width
    BeadRowParams row;  // the halo's or the band's small stones
};

// `centre`: the centre stone (every kind but the band); `small`: the halo's or band's stones or
// the three-stone ring's side stones (every kind but the solitaire). Stones come at their final
// size. Errors name the parameter (its key in a piece file) and what is wrong.
Result<Piece> make_setting(const SettingParams& params, const std::string& name,
                           std::optional<Stone> centre, std::optional<Stone> small);

}  // namespace gem
