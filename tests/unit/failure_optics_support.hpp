#pragma once
// Shared pieces of the failure_optics_* tests: catalogue indices, a round brilliant in a
// constant-index material, one small orthographic view traced pixel by pixel, the energy
// balance of a ray-list and the error bound of a value stored as binary16.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gemdb/database_types.hpp"
#include "gemdb/quantise.hpp"
#include "gemdb/view_grid.hpp"
#include "geometry/cuts.hpp"
#include "optics/material.hpp"
#include "trace/tracer.hpp"

namespace gem::failure_test {

// n at the sodium D line from the built-in catalogue (moissanite 2.648, diamond 2.417, quartz
// 1.544, crown glass 1.517 are the published values the catalogue cites).
inline double catalogue_index(const std::string& name) {
    const std::optional<Material> m = find_material(name);
    if (!m) {
        ADD_FAILURE() << "no catalogue material " << name;
        return 1.5;
    }
    return m->index(kFraunhoferD);
}

inline Stone round_brilliant(double n) {
    Material m;
    m.name = "n=" + std::to_string(n);
    m.dispersion = Dispersion::constant_index(n);
    Result<Stone> stone = make_cut(default_cut_params(CutShape::round_brilliant), m);
    if (!stone) {
        ADD_FAILURE() << stone.error();
        return {};
    }
    return std::move(stone).value();
}

// A view a little off the table axis (so crown and pavilion facets both show), as the kiosk
// shows a stone face-up on the counter.
inline glm::dvec3 face_up_view() {
    return glm::normalize(glm::dvec3(0.25, 1.0, 0.15));
}

// side² ray-lists of an orthographic view along `view` whose square window `field_mm` wide
// frames the stone, row-major, row 0 at the top: what a table of that view stores.
inline std::vector<RayList> trace_view(const Tracer& tracer, double ior,
                                       const TraceSettings& settings, const glm::dvec3& view,
                                       std::uint32_t side, double field_mm) {
    const CameraModel camera{CameraModel::Kind::orthographic, 0.0, field_mm};
    const CameraBasis basis = canonical_basis(view);
    std::vector<RayList> lists(static_cast<std::size_t>(side) * side);
    for (std::uint32_t row = 0; row < side; ++row) {
        for (std::uint32_t col = 0; col < side; ++col) {
            const Ray ray = camera_ray(camera, basis, pixel_centre(col, row, side, field_mm));
            tracer.trace(ray, ior, settings, lists[static_cast<std::size_t>(row) * side + col]);
        }
    }
    return lists;
}

// quantise.hpp's stated bound on the error of one value stored as binary16, plus the rounding
// to float the encoder makes first (2^-24 relative).
inline double half_bound(double x) {
    const double a = std::abs(x);
    return std::max(kHalfMaxRelativeError * a, kHalfMaxSubnormalError) + std::ldexp(a, -24);
}

// reflected + exits + truncated: 1 with no absorption.
inline double energy(const RayList& list) {
    double sum = list.reflected.weight + list.truncated_weight;
    for (const TracedRay& e : list.exits) sum += e.weight;
    return sum;
}

inline bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Every number in a ray-list finite, every direction unit length.
inline bool all_finite(const RayList& list) {
    auto good = [](const TracedRay& r) {
        return finite(r.origin) && finite(r.direction) && std::isfinite(r.weight) &&
               std::isfinite(r.path_mm) && std::abs(glm::length(r.direction) - 1.0) < 1e-9;
    };
    if (!std::isfinite(list.truncated_weight) || !good(list.reflected)) return false;
    for (const TracedRay& e : list.exits) {
        if (!good(e)) return false;
    }
    return true;
}

}  // namespace gem::failure_test
