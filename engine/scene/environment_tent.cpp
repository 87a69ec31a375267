// The light tent of product photography: the stone sits in a white translucent tent lit from
// outside, brightest overhead, with a few black flags (cards) standing round it. A white
// surround alone would wash a diamond out to grey; the flags give its facets the dark
// patterns that read as contrast, and the band of a ring bright and dark reflections.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "scene/environment.hpp"

namespace gem {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr int kWidth = 1024;  // equirectangular texels; the flags' edges span a few
constexpr int kHeight = 512;

struct Flag {
    double azimuth_deg;  // from +z toward +x
    double half_width_deg;
    double bottom_deg;  // elevation of its lower and upper edge
    double top_deg;
};

// Tuned by eye on the round diamond in its ring at the kiosk's start view.
constexpr std::array<Flag, 6> kFlags{{
    {0.0, 14.0, -15.0, 50.0},
    {60.0, 10.0, -10.0, 35.0},
    {120.0, 14.0, -15.0, 50.0},
    {180.0, 10.0, -10.0, 35.0},
    {240.0, 14.0, -15.0, 50.0},
    {300.0, 10.0, -10.0, 35.0},
}};
constexpr double kEdgeDeg = 2.0;  // every edge ramps over this many degrees
constexpr double kFlagRadiance = 0.015;

double smooth(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// 1 inside [low, high], 0 outside, ramped over kEdgeDeg.
double inside(double x, double low, double high) {
    return smooth(low - 0.5 * kEdgeDeg, low + 0.5 * kEdgeDeg, x) *
           (1.0 - smooth(high - 0.5 * kEdgeDeg, high + 0.5 * kEdgeDeg, x));
}

double wrap_deg(double a) {
    return a - 360.0 * std::floor((a + 180.0) / 360.0);
}

glm::vec3 tent_radiance(double azimuth_deg, double elevation_deg) {
    // Walls 0.8, rising to 1.6 overhead; the white sweep below a little darker.
    double level =
        0.8 + 0.8 * smooth(20.0, 80.0, elevation_deg) - 0.2 * smooth(0.0, -40.0, elevation_deg);
    for (const Flag& f : kFlags) {
        const double across = wrap_deg(azimuth_deg - f.azimuth_deg);
        const double w = inside(across, -f.half_width_deg, f.half_width_deg) *
                         inside(elevation_deg, f.bottom_deg, f.top_deg);
        level = level * (1.0 - w) + kFlagRadiance * w;
    }
    return glm::vec3(static_cast<float>(level));
}

}  // namespace

Environment Environment::light_tent() {
    std::vector<glm::vec3> pixels(static_cast<std::size_t>(kWidth) * kHeight);
    for (int y = 0; y < kHeight; ++y) {
        // The inverse of image_radiance's mapping: rows from +y down, the centre column -z.
        const double theta = (y + 0.5) / kHeight * std::numbers::pi;
        const double elevation = 90.0 - theta / kDegree;
        for (int x = 0; x < kWidth; ++x) {
            const double longitude = ((x + 0.5) / kWidth - 0.5) * 2.0 * std::numbers::pi;
            const glm::dvec3 d(std::sin(theta) * std::sin(longitude), std::cos(theta),
                               -std::sin(theta) * std::cos(longitude));
            const double azimuth = std::atan2(d.x, d.z) / kDegree;
            pixels[static_cast<std::size_t>(y) * kWidth + x] = tent_radiance(azimuth, elevation);
        }
    }
    return from_pixels(kWidth, kHeight, std::move(pixels));
}

}  // namespace gem
