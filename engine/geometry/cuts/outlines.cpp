// Girdle outlines for the brilliant-pattern shapes. Each is parameterised so that the main
// facets at t = k·45° fall where a cutter puts them: on the axes and half way between, with
// the pointed tips of marquise, pear and princess at sample points.

#include <cmath>

#include "geometry/cuts/cut_internal.hpp"

namespace gem::cuts {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The outline for t in (π, 2π) as the mirror image (z → −z) of t' = 2π − t.
OutlinePoint mirrored_below(const std::function<OutlinePoint(double)>& upper, double t) {
    if (t <= kPi) return upper(t);
    OutlinePoint q = upper(2.0 * kPi - t);
    q.p.y = -q.p.y;
    q.n.y = -q.n.y;
    return q;
}

double sign(double v) {
    return v < 0.0 ? -1.0 : 1.0;
}

// cos(π/2) is 6e-17, not 0; under a square root that would move a point on an axis by 1e-8.
double snap(double v) {
    return std::abs(v) < 1e-12 ? 0.0 : v;
}

}  // namespace

Outline round_outline(double radius) {
    return [radius](double t) {
        const glm::dvec2 u(std::cos(t), std::sin(t));
        return OutlinePoint{radius * u, u};
    };
}

Outline oval_outline(double length, double width) {
    const double a = length / 2.0, b = width / 2.0;
    return [a, b](double t) {
        return OutlinePoint{{a * std::cos(t), b * std::sin(t)},
                            glm::normalize(glm::dvec2(b * std::cos(t), a * std::sin(t)))};
    };
}

// Two circular arcs through the tips (±L/2, 0) and the sides (0, ±W/2). The upper arc's
// centre is (0, −c) with radius W/2 + c, where (W/2 + c)² = (L/2)² + c².
Outline marquise_outline(double length, double width) {
    const double c = (length * length - width * width) / (4.0 * width);
    const double radius = width / 2.0 + c;
    const double tip_angle = std::atan2(c, length / 2.0);
    auto upper = [=](double t) {
        if (t == 0.0 || t == kPi)
            return OutlinePoint{{t == 0.0 ? length / 2 : -length / 2, 0.0},
                                {t == 0.0 ? 1.0 : -1.0, 0.0}};
        const double a = tip_angle + (kPi - 2.0 * tip_angle) * t / kPi;
        const glm::dvec2 u(std::cos(a), std::sin(a));
        return OutlinePoint{glm::dvec2(0.0, -c) + radius * u, u};
    };
    return [upper](double t) { return mirrored_below(upper, t); };
}

// A half circle of diameter W (the round end, toward −x) and, toward the tip at (L/2, 0), two
// arcs tangent to it where it is widest. The stone is centred on its length.
Outline pear_outline(double length, double width) {
    const double x0 = (width - length) / 2.0;  // centre of the round end
    const double reach = length / 2.0 - x0;    // from x0 to the tip
    const double radius = (reach * reach + width * width / 4.0) / width;
    const glm::dvec2 centre(x0, width / 2.0 - radius);
    const double tip_angle = std::atan2(radius - width / 2.0, reach);
    auto upper = [=](double t) {
        if (t == 0.0) return OutlinePoint{{length / 2.0, 0.0}, {1.0, 0.0}};
        if (t < kPi / 2.0) {
            const double a = tip_angle + (kPi / 2.0 - tip_angle) * t / (kPi / 2.0);
            const glm::dvec2 u(std::cos(a), std::sin(a));
            return OutlinePoint{centre + radius * u, u};
        }
        const glm::dvec2 u(std::cos(t), std::sin(t));
        return OutlinePoint{glm::dvec2(x0, 0.0) + width / 2.0 * u, u};
    };
    return [upper](double t) { return mirrored_below(upper, t); };
}

// A superellipse |x/a|⁴ + |z/b|⁴ = 1: a square with rounded corners and gently curved sides.
Outline cushion_outline(double length, double width) {
    const double a = length / 2.0, b = width / 2.0;
    return [a, b](double t) {
        const double c = snap(std::cos(t)), s = snap(std::sin(t));
        const glm::dvec2 p(a * sign(c) * std::sqrt(std::abs(c)),
                           b * sign(s) * std::sqrt(std::abs(s)));
        const glm::dvec2 grad(sign(c) * std::pow(std::abs(p.x / a), 3.0) / a,
                              sign(s) * std::pow(std::abs(p.y / b), 3.0) / b);
        return OutlinePoint{p, glm::normalize(grad)};
    };
}

// A rectangle with sharp corners at t = 45° + k·90° whose sides bulge by kPrincessBulge·W
// (parabolic arcs). With straight sides the bezel at a side's middle would contain that side's
// whole girdle edge, and the upper girdles beside it would coincide with it.
constexpr double kPrincessBulge = 0.03;

Outline princess_outline(double length, double width) {
    const double sag = kPrincessBulge * width;
    const double a = length / 2.0 - sag, b = width / 2.0 - sag;  // the corners
    return [=](double t) {
        const double c = snap(std::cos(t)), s = snap(std::sin(t));
        // Side x = ±(a + sag(1 − (z/b)²)) and side z = ±(b + sag(1 − (x/a)²)), u along the side.
        const double u_x = s / std::max(std::abs(c), 1e-300),
                     u_z = c / std::max(std::abs(s), 1e-300);
        const glm::dvec2 n_x = glm::normalize(glm::dvec2(sign(c), 2.0 * sag * u_x / b));
        const glm::dvec2 n_z = glm::normalize(glm::dvec2(2.0 * sag * u_z / a, sign(s)));
        if (std::abs(std::abs(c) - std::abs(s)) < 1e-9) {
            return OutlinePoint{{a * sign(c), b * sign(s)}, glm::normalize(n_x + n_z)};
        }
        if (std::abs(c) > std::abs(s)) {
            return OutlinePoint{{sign(c) * (a + sag * (1.0 - u_x * u_x)), b * u_x}, n_x};
        }
        return OutlinePoint{{a * u_z, sign(s) * (b + sag * (1.0 - u_z * u_z))}, n_z};
    };
}

}  // namespace gem::cuts
