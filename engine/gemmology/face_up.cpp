#include "gemmology/face_up.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gemmology/fire_spread.hpp"
#include "optics/material.hpp"
#include "trace/parallel.hpp"

namespace gem {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Rotation by `angle` about the unit `axis` (Rodrigues' formula).
glm::dmat3 rotation(const glm::dvec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const glm::dmat3 k(0.0, axis.z, -axis.y, -axis.z, 0.0, axis.x, axis.y, -axis.x, 0.0);
    return glm::dmat3(1.0) + s * k + (1.0 - c) * (k * k);
}

// Adds the ray's weight to its zone and, where it sees the lit sky, to the light return;
// `to_room` takes stone-frame directions to the room's frame, where the sky is defined.
void add_ray(const SkyModel& sky, const glm::dmat3& to_room, const TracedRay& ray,
             FaceUpPixel& px) {
    const glm::dvec3 d = to_room * ray.direction;
    px.zone[static_cast<std::size_t>(sky.zone(d))] += static_cast<float>(ray.weight);
    px.light_return += static_cast<float>(ray.weight * sky.radiance_along(d));
}

double girdle_radius(const Stone& stone) {
    double r = 0.0;
    for (const glm::dvec3& v : stone.vertices) r = std::max(r, std::hypot(v.x, v.z));
    return r;
}

// Adds one pixel's or one view's figures to `t` (both carry the same named fields).
template <class Figures>
void add_figures(FaceUpTotals& t, const Figures& f) {
    t.light_return += f.light_return;
    t.surface_return += f.surface_return;
    for (std::size_t z = 0; z < t.zone.size(); ++z) t.zone[z] += f.zone[z];
    t.truncated += f.truncated;
    t.fire_deg += f.fire_deg;
}

// Sums over n items to means; the mean spread is fire over the lit exit weight behind it.
void finish_means(FaceUpTotals& t, double n, double spread_weight) {
    if (n > 0.0) {
        t.light_return /= n;
        t.surface_return /= n;
        for (double& z : t.zone) z /= n;
        t.truncated /= n;
        t.mean_spread_deg = spread_weight > 0.0 ? t.fire_deg / spread_weight : 0.0;
        t.fire_deg /= n;
    }
    t.leakage = t.zone[static_cast<std::size_t>(SkyZone::below)];
    t.hemisphere_return = t.zone[0] + t.zone[1] + t.zone[2];  // low sky, high sky, head
}

}  // namespace

FaceUpAnalysis analyse_face_up(const Stone& stone, const FaceUpSettings& settings) {
    FaceUpAnalysis a;
    a.resolution = std::max(settings.resolution, 1);
    a.girdle_radius_mm = girdle_radius(stone);
    a.pixels.assign(static_cast<std::size_t>(a.resolution) * a.resolution, FaceUpPixel{});
    double reach = 0.0;  // rays start outside the stone's bounding sphere
    for (const glm::dvec3& v : stone.vertices) reach = std::max(reach, glm::length(v));
    reach += 1.0;
    const double pixel = 2.0 * a.girdle_radius_mm / a.resolution;
    const double n_d = stone.material.index(kFraunhoferD);
    const double n_red = stone.material.index(kFraunhoferC);
    const double n_blue = stone.material.index(kFraunhoferF);
    const Tracer tracer(stone);
    // The room turned about the stone: the eye's direction, and the picture's axes, in the
    // stone frame. With no tilt: looking down -y, x to the right, +z down the picture.
    const double az = settings.tilt_azimuth_deg * kDeg;
    const glm::dmat3 to_stone =
        rotation({std::sin(az), 0.0, -std::cos(az)}, settings.tilt_deg * kDeg);
    const glm::dmat3 to_room = glm::transpose(to_stone);
    const glm::dvec3 eye = to_stone * glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 across = to_stone * glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 down = to_stone * glm::dvec3(0.0, 0.0, 1.0);

    parallel_for(static_cast<std::size_t>(a.resolution), [&](std::size_t begin, std::size_t end) {
        RayList list, red, blue;  // reused along the rows
        std::vector<double> spread;
        for (auto y = static_cast<int>(begin); y < static_cast<int>(end); ++y) {
            for (int x = 0; x < a.resolution; ++x) {
                const double px_x = -a.girdle_radius_mm + (x + 0.5) * pixel;
                const double px_z = -a.girdle_radius_mm + (y + 0.5) * pixel;
                const Ray ray{px_x * across + px_z * down + reach * eye, -eye};
                tracer.trace(ray, n_d, settings.trace, list);
                if (!list.hit) continue;
                FaceUpPixel& px = a.pixels[static_cast<std::size_t>(y) * a.resolution + x];
                px.stone = true;
                px.table = stone.facets[list.reflected.facet].kind == FacetKind::table;
                px.radius = static_cast<float>(std::hypot(px_x, px_z) / a.girdle_radius_mm);
                add_ray(settings.sky, to_room, list.reflected, px);
                px.surface_return = px.light_return;
                px.surface_weight = static_cast<float>(list.reflected.weight);
                px.surface_zone = settings.sky.zone(to_room * list.reflected.direction);
                for (const TracedRay& e : list.exits) {
                    add_ray(settings.sky, to_room, e, px);
                    if (stone.facets[e.facet].kind == FacetKind::girdle) {
                        px.girdle_exit += static_cast<float>(e.weight);
                    }
                }
                px.truncated = static_cast<float>(list.truncated_weight);
                if (!settings.fire) continue;
                tracer.trace(ray, n_red, settings.trace, red);
                tracer.trace(ray, n_blue, settings.trace, blue);
                colour_spread_deg(list, red, blue, spread);
                for (std::size_t k = 0; k < list.exits.size(); ++k) {
                    const TracedRay& e = list.exits[k];
                    const double lit =
                        e.weight * settings.sky.radiance_along(to_room * e.direction);
                    if (spread[k] < 0.0 || lit <= 0.0) continue;
                    px.fire_deg += static_cast<float>(lit * spread[k]);
                    px.spread_weight += static_cast<float>(lit);
                }
            }
        }
    });

    FaceUpTotals& t = a.totals;
    double spread_weight = 0.0;
    for (const FaceUpPixel& px : a.pixels) {
        if (!px.stone) continue;
        ++t.stone_pixels;
        add_figures(t, px);
        spread_weight += px.spread_weight;
    }
    finish_means(t, t.stone_pixels, spread_weight);
    return a;
}

FaceUpTotals tilt_averaged_totals(const Stone& stone, const FaceUpSettings& settings,
                                  const std::vector<ViewTilt>& views) {
    FaceUpTotals mean;
    double spread_weight = 0.0;
    for (const ViewTilt& v : views) {
        FaceUpSettings s = settings;
        s.tilt_deg = v.tilt_deg;
        s.tilt_azimuth_deg = v.azimuth_deg;
        const FaceUpTotals t = analyse_face_up(stone, s).totals;
        mean.stone_pixels += t.stone_pixels;
        add_figures(mean, t);
        if (t.mean_spread_deg > 0.0) spread_weight += t.fire_deg / t.mean_spread_deg;
    }
    if (views.empty()) return mean;
    const double n = static_cast<double>(views.size());
    mean.stone_pixels = static_cast<int>(mean.stone_pixels / n);
    finish_means(mean, n, spread_weight);
    return mean;
}

double mean_light_return(const FaceUpAnalysis& analysis, double r0, double r1, int* count) {
    double sum = 0.0;
    int n = 0;
    for (const FaceUpPixel& px : analysis.pixels) {
        if (!px.stone || px.radius < r0 || px.radius >= r1) continue;
        sum += px.light_return;
        ++n;
    }
    if (count != nullptr) *count = n;
    return n > 0 ? sum / n : 0.0;
}

std::vector<double> radial_profile(const FaceUpAnalysis& analysis, int bins,
                                   float FaceUpPixel::*value,
                                   const std::vector<double>& azimuths_deg, double half_wedge_deg) {
    std::vector<double> sum(static_cast<std::size_t>(bins), 0.0);
    std::vector<int> count(static_cast<std::size_t>(bins), 0);
    const double pixel = 2.0 / analysis.resolution;  // in girdle radii
    for (int y = 0; y < analysis.resolution; ++y) {
        for (int x = 0; x < analysis.resolution; ++x) {
            const FaceUpPixel& px = analysis.at(x, y);
            if (!px.stone) continue;
            if (!azimuths_deg.empty()) {
                const double az = std::atan2(-1.0 + (y + 0.5) * pixel, -1.0 + (x + 0.5) * pixel) *
                                  180.0 / std::numbers::pi;
                bool inside = false;
                for (double a : azimuths_deg) {
                    const double d = std::remainder(az - a, 360.0);
                    inside = inside || std::abs(d) <= half_wedge_deg;
                }
                if (!inside) continue;
            }
            const int bin = static_cast<int>(px.radius * bins);
            if (bin < 0 || bin >= bins) continue;
            sum[std::size_t(bin)] += px.*value;
            ++count[std::size_t(bin)];
        }
    }
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] = count[i] > 0 ? sum[i] / count[i] : -1.0;
    return sum;
}

}  // namespace gem
