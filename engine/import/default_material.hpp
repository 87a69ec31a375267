#pragma once
// Private: the materials the importers fall back on when the caller gives none.

#include <string>

#include "optics/material.hpp"

namespace gem::import {

// Meshes carry no optical data. Crown glass (BK7, n_d = 1.5168, Schott data sheet) is what a
// glass model of a stone is usually made of; it is built here rather than looked up in the
// material catalogue so the importers do not depend on it.
inline Material crown_glass() {
    Material m;
    m.name = "crown glass";
    m.dispersion = Dispersion::constant_index(1.5168);
    return m;
}

// A GemCad design's "I" line: the index the designer optimised the angles for.
inline Material gemcad_index_material(double index, const std::string& as_written) {
    Material m;
    m.name = "GemCad design index " + as_written;
    m.dispersion = Dispersion::constant_index(index);
    return m;
}

}  // namespace gem::import
