#include "views.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gem::accuracy {

double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
    const double c = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

glm::dvec3 on_view(const ViewGrid& grid, const glm::dvec3& target) {
    const ViewMatch m = grid.nearest(target);
    // group()[g] · asked ≈ stored, and g is orthogonal, so asked ≈ gᵀ · stored.
    return glm::normalize(glm::transpose(grid.group()[m.symmetry]) * grid.direction(m.view));
}

glm::dvec3 between_view(const ViewGrid& grid, const glm::dvec3& target) {
    // A golden-angle spiral over the cap of radius one spacing about the target: dense enough
    // (400 points) to come within a few per cent of the largest gap.
    const glm::dvec3 t = glm::normalize(target);
    const glm::dvec3 helper = std::abs(t.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, t));
    const glm::dvec3 v = glm::cross(t, u);
    const double radius = grid.spec().spacing_rad;
    glm::dvec3 best = t;
    double best_angle = -1.0;
    constexpr int kCandidates = 400;
    for (int i = 0; i < kCandidates; ++i) {
        const double r = radius * std::sqrt((i + 0.5) / kCandidates);
        const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
        const glm::dvec3 d =
            glm::normalize(std::cos(r) * t + std::sin(r) * (std::cos(phi) * u + std::sin(phi) * v));
        const double a = grid.nearest(d).angle;
        if (a > best_angle) {
            best_angle = a;
            best = d;
        }
    }
    return best;
}

std::vector<glm::dvec3> view_path(const ViewGrid& grid, const glm::dvec3& target, int count,
                                  double beyond) {
    const glm::dvec3 a = on_view(grid, target);
    const std::uint32_t own = grid.nearest(target).view;
    // The nearest image of another stored view (images of a's own view show the same table,
    // mirrored or turned: no gap to cross).
    glm::dvec3 b = a;
    double nearest = 1e9;
    for (std::uint32_t view = 0; view < grid.size(); ++view) {
        if (view == own) continue;
        const glm::dvec3& s = grid.direction(view);
        for (const glm::dmat3& h : grid.group()) {
            const glm::dvec3 d = h * s;
            const double ang = angle_deg(a, d);
            if (ang > 1e-6 && ang < nearest) {
                nearest = ang;
                b = d;
            }
        }
    }
    const double omega = nearest * std::numbers::pi / 180.0;
    std::vector<glm::dvec3> path;
    for (int k = 0; k < count; ++k) {
        const double t = beyond * k / (count - 1);
        path.push_back(glm::normalize(std::sin((1.0 - t) * omega) * a + std::sin(t * omega) * b));
    }
    return path;
}

}  // namespace gem::accuracy
