#pragma once
// Checks that a stone is a valid closed solid; used by tests, importers and cut builders.

#include <string>
#include <vector>

#include "geometry/stone.hpp"

namespace gem {

struct SolidReport {
    int euler_characteristic = 0;       // V − E + F over facets (2 for a sphere-like solid)
    bool closed = false;                // every edge shared by exactly two facets, opposite winding
    bool outward = false;               // facet normals point out (winding agrees with planes)
    bool planar = false;                // facet vertices lie on their planes
    double volume = 0.0;                // mm³, from the triangle mesh (divergence theorem)
    double area = 0.0;                  // mm²
    std::vector<std::string> problems;  // human-readable, empty when valid
    bool valid() const { return problems.empty(); }
};

SolidReport check_solid(const Stone& stone, double tolerance = 1e-9);

// Facets a gemmologist counts (everything but girdle facets).
int gemmological_facet_count(const Stone& stone);

// True when every matrix in stone.symmetry maps the vertex set onto itself.
bool symmetry_holds(const Stone& stone, double tolerance = 1e-9);

}  // namespace gem
