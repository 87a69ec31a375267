// Point groups of the cuts as orthogonal matrices in the stone frame (y is the table axis).

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/cuts/cut_internal.hpp"

namespace gem::cuts {

std::vector<glm::dmat3> mirror_group(const glm::dvec3& mirror_normal) {
    const glm::dvec3 m = glm::normalize(mirror_normal);
    return {glm::dmat3(1.0), glm::dmat3(1.0) - 2.0 * glm::outerProduct(m, m)};
}

std::vector<glm::dmat3> cnv_group(int n) {
    const double pi = 3.14159265358979323846;
    std::vector<glm::dmat3> group;
    for (int k = 0; k < n; ++k) {
        group.emplace_back(glm::rotate(glm::dmat4(1.0), 2.0 * pi * k / n, glm::dvec3(0, 1, 0)));
    }
    // Mirror k contains the horizontal direction at azimuth π·k/n (k = 0: the x axis).
    for (int k = 0; k < n; ++k) {
        const double a = pi * k / n;
        group.push_back(mirror_group(glm::dvec3(-std::sin(a), 0.0, std::cos(a)))[1]);
    }
    return group;
}

}  // namespace gem::cuts
