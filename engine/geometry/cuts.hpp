#pragma once
// Parametric cuts with gemmologists' parameters. Every cut is built from facet planes and is a
// valid closed solid (see validate.hpp); the heart, whose cleft makes it non-convex, is glued
// from two mirrored convex halves.

#include <optional>
#include <string>
#include <string_view>

#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem {

enum class CutShape { round_brilliant, princess, emerald, oval, marquise, pear, heart, cushion };

std::optional<CutShape> parse_cut_shape(std::string_view name);  // "round", "round-brilliant", ...
const char* to_string(CutShape shape);

struct CutParams {
    CutShape shape = CutShape::round_brilliant;
    double width_mm = 6.5;              // girdle diameter (the short side for fancy shapes)
    double length_to_width = 1.0;       // fancy shapes; 1 for round
    double table_pct = 53.0;            // table width / girdle width (Tolkowsky 53 %)
    double crown_angle_deg = 34.5;      // Tolkowsky 34.5°
    double pavilion_angle_deg = 40.75;  // Tolkowsky 40.75°
    double girdle_pct = 2.0;            // girdle thickness / width, at the main facets
    double star_pct = 50.0;             // star length, share of table edge → girdle
    double lower_girdle_pct = 75.0;     // lower-girdle length, share of girdle → culet
    double culet_pct = 0.0;             // culet width / girdle width; 0 = pointed (no culet facet)
    bool faceted_girdle = true;         // faceted girdle, or a smooth (finely polygonised) one
};

// The customary parameters for a shape (Tolkowsky for round; typical L/W for fancy shapes).
CutParams default_cut_params(CutShape shape);

// Builds the stone; parameters out of range give an error naming the parameter.
Result<Stone> make_cut(const CutParams& params, const Material& material);

}  // namespace gem
