#pragma once
// The parametric cuts the tracer tests run on: every shape with its customary parameters, in
// diamond (n = 2.417 at the sodium D line; GIA, "Gem Reference Guide", 1995).

#include <gtest/gtest.h>

#include <vector>

#include "geometry/cuts.hpp"
#include "optics/material.hpp"

namespace gem::test {

inline constexpr double kDiamondIndex = 2.417;

inline Material constant_index_material(double n) {
    Material m;
    m.name = "test material";
    m.dispersion.kind = Dispersion::Kind::constant;
    m.dispersion.coef = {n};
    return m;
}

// A Tolkowsky round brilliant of the given girdle width in the catalogue's diamond.
inline Stone round_diamond(double width_mm) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.width_mm = width_mm;
    return make_cut(p, find_material("diamond").value()).value();
}

inline constexpr CutShape kAllCuts[] = {
    CutShape::round_brilliant, CutShape::princess, CutShape::emerald, CutShape::oval,
    CutShape::marquise,        CutShape::pear,     CutShape::heart,   CutShape::cushion};

// Every cut at its default parameters; a cut that does not build fails the calling test.
inline std::vector<Stone> all_cuts() {
    std::vector<Stone> stones;
    for (CutShape shape : kAllCuts) {
        Result<Stone> stone =
            make_cut(default_cut_params(shape), constant_index_material(kDiamondIndex));
        if (!stone) {
            ADD_FAILURE() << to_string(shape) << ": " << stone.error();
            continue;
        }
        stones.push_back(std::move(stone).value());
    }
    return stones;
}

}  // namespace gem::test
