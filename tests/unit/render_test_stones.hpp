#pragma once
// Small stones with known answers for the render tests, built from planes here so the tests
// do not depend on the parametric cuts.

#include <string>
#include <vector>

#include "geometry/polyhedron.hpp"

namespace gem::render_test {

// The axis-aligned cube |x|, |y|, |z| <= half, in a colourless constant-index material.
inline Stone cube(double half, double ior, glm::dvec3 absorption_per_mm = glm::dvec3(0.0)) {
    std::vector<FacetPlane> planes;
    const glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const glm::dvec3& a : axes) {
        for (double sign : {1.0, -1.0}) {
            FacetPlane p;
            p.plane.n = sign * a;
            p.plane.d = half;
            planes.push_back(p);
        }
    }
    Result<Stone> stone = stone_from_planes(planes, "cube");
    assert(stone.ok());
    Stone s = std::move(stone).value();
    s.material.name = "test glass";
    s.material.dispersion = Dispersion::constant_index(ior);
    s.material.body_colour = glm::dvec3(1.0);
    s.material.absorption_per_mm = absorption_per_mm;
    return s;
}

}  // namespace gem::render_test
