// The procedural studio. Diamonds sparkle when their facets show small bright sources against
// a dark surround, so the studio is mostly dark with a few softboxes; the edges of every
// light are smooth ramps a few degrees wide so that pixels do not alias on them.
#include <algorithm>
#include <array>
#include <cmath>

#include "scene/environment.hpp"

namespace gem {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

struct SoftboxSpec {
    double azimuth_deg;    // from +z toward +x
    double elevation_deg;  // above the girdle plane
    double half_width_deg;
    double half_height_deg;
    glm::dvec3 radiance;
};

// Tuned by eye on renders of a round diamond, an oval sapphire and an emerald cut.
constexpr std::array<SoftboxSpec, 7> kSoftboxes{{
    {20.0, 58.0, 16.0, 12.0, {2.6, 2.6, 2.5}},
    {110.0, 62.0, 13.0, 14.0, {2.2, 2.2, 2.3}},
    {200.0, 55.0, 17.0, 11.0, {2.4, 2.4, 2.4}},
    {290.0, 60.0, 12.0, 15.0, {2.3, 2.3, 2.2}},
    {65.0, 25.0, 5.0, 14.0, {1.6, 1.6, 1.7}},
    {245.0, 22.0, 6.0, 12.0, {1.5, 1.5, 1.5}},
    {155.0, 30.0, 3.5, 3.5, {3.0, 3.0, 3.0}},
}};

constexpr double kSoftEdge = 0.04;  // width of each light's edge ramp, in tangent units

struct Softbox {
    glm::dvec3 centre;  // unit direction
    glm::dvec3 across;  // horizontal tangent
    glm::dvec3 along;   // tangent toward the zenith
    double half_across;
    double half_along;
    glm::dvec3 radiance;
};

std::array<Softbox, kSoftboxes.size()> make_softboxes() {
    std::array<Softbox, kSoftboxes.size()> boxes{};
    for (std::size_t i = 0; i < kSoftboxes.size(); ++i) {
        const SoftboxSpec& s = kSoftboxes[i];
        const double az = s.azimuth_deg * kDegree;
        const double el = s.elevation_deg * kDegree;
        Softbox& b = boxes[i];
        b.centre = {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
        b.across = {std::cos(az), 0.0, -std::sin(az)};
        b.along = glm::cross(b.across, b.centre);
        if (b.along.y < 0.0) b.along = -b.along;
        b.half_across = std::tan(s.half_width_deg * kDegree);
        b.half_along = std::tan(s.half_height_deg * kDegree);
        b.radiance = s.radiance;
    }
    return boxes;
}

// 1 inside |x| < half, 0 outside, a smooth cubic ramp across the edge.
double soft_inside(double x, double half) {
    const double t = std::clamp((half + 0.5 * kSoftEdge - std::abs(x)) / kSoftEdge, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

glm::dvec3 Environment::studio_radiance(const glm::dvec3& d) const {
    static const std::array<Softbox, kSoftboxes.size()> boxes = make_softboxes();
    // Surround: a dark counter below, walls a little brighter toward the horizon, a dark
    // ceiling; smooth in elevation.
    const double y = std::clamp(d.y, -1.0, 1.0);
    glm::dvec3 colour;
    if (y < 0.0) {
        colour = glm::dvec3(0.018, 0.017, 0.016) * (1.0 + y * 0.5);
    } else {
        const double wall = std::exp(-4.0 * y);
        colour = glm::dvec3(0.02, 0.02, 0.021) + glm::dvec3(0.12, 0.12, 0.125) * wall;
    }
    for (const Softbox& b : boxes) {
        const double c = glm::dot(d, b.centre);
        if (c <= 0.2) continue;
        // Gnomonic projection onto the softbox's plane: rectangles stay rectangles.
        const double u = glm::dot(d, b.across) / c;
        const double v = glm::dot(d, b.along) / c;
        const double w = soft_inside(u, b.half_across) * soft_inside(v, b.half_along);
        colour += w * b.radiance;
    }
    return colour;
}

}  // namespace gem
