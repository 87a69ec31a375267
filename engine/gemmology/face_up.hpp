#pragma once
// Face-up light return, leakage, ASET zones and fire of a stone, measured with the exact
// tracer. The viewer looks down the table axis (-y; or tilted, see FaceUpSettings),
// orthographically (docs/design.md, "Contracts": a stone seen from a counter is almost
// orthographic); one ray per pixel of a square grid that just covers the girdle is traced
// backwards from the eye into the stone, and every ray that comes out (the first surface
// reflection and each exit after internal bounces) carries its exact Fresnel weight to whatever
// it sees of the sky model (sky.hpp).
//
// Definitions (per stone pixel, i.e. per ray that hits the stone; totals are means over them):
//  - light return: Σ over the pixel's rays of weight × sky radiance along the ray (the lit
//    sky has radiance 1, the head and everything below the girdle plane 0). Including the
//    first surface reflection ("external lustre") as OctoNus' LR_MSU does; GIA's WLR left it
//    out (Hemphill et al., Gems & Gemology 34(3), 1998). `surface_return` is that part alone.
//  - hemisphere return: the weight of every ray going back up above the girdle plane, the head
//    counted as lit; GIA's "light return" into the upper hemisphere (Hemphill et al. 1998),
//    OctoNus' LR_GIA. With the tracer's weights it is 1 − leakage − truncated.
//  - zone weights: the same weights sorted by the ASET zone of each ray's direction; leakage is
//    the weight of exits pointing below the girdle plane (nearly all through the pavilion).
//  - fire: Σ over lit exits of weight × the C–F angular spread of that path (fire_spread.hpp),
//    in degrees: light return weighted by how far it is fanned into colours. The mean spread is
//    fire / the lit exit weight that has a spread.
// With no absorption the weights of a pixel add up to 1 less `truncated` (energy left inside
// where the tracer cut the ray tree).

#include <array>
#include <vector>

#include "gemmology/sky.hpp"
#include "geometry/stone.hpp"
#include "trace/tracer.hpp"

namespace gem {

struct FaceUpSettings {
    int resolution = 128;  // pixels across the girdle diameter
    SkyModel sky;
    TraceSettings trace{.max_depth = 16, .min_weight = 1e-4};
    bool fire = true;  // also trace each pixel at n(C) and n(F) (three traces per pixel)
    // The stone rocked in the hand: the room (sky and viewer together) turned about the stone
    // by `tilt_deg` toward the azimuth `tilt_azimuth_deg` (measured about +y from +x toward
    // +z). 0: face-up. The picture plane stays perpendicular to the line of sight.
    double tilt_deg = 0.0;
    double tilt_azimuth_deg = 0.0;
};

struct ViewTilt {
    double tilt_deg = 0.0;
    double azimuth_deg = 0.0;
};

struct FaceUpPixel {
    bool stone = false;   // the pixel's ray hits the stone
    bool table = false;   // ... and enters through the table
    float radius = 0.0f;  // distance from the axis / girdle radius
    float light_return = 0.0f;
    float surface_return = 0.0f;
    float surface_weight = 0.0f;  // Fresnel weight of the first reflection, in `zone` too
    SkyZone surface_zone = SkyZone::head;
    std::array<float, kSkyZoneCount> zone{};  // weight per SkyZone
    float truncated = 0.0f;
    float girdle_exit = 0.0f;  // weight of exits through girdle facets
    float fire_deg = 0.0f;
    float spread_weight = 0.0f;  // lit exit weight whose spread is known
};

struct FaceUpTotals {
    int stone_pixels = 0;
    double light_return = 0.0;
    double surface_return = 0.0;
    double hemisphere_return = 0.0;
    std::array<double, kSkyZoneCount> zone{};
    double leakage = 0.0;  // = zone[below]
    double truncated = 0.0;
    double fire_deg = 0.0;
    double mean_spread_deg = 0.0;
};

struct FaceUpAnalysis {
    int resolution = 0;
    double girdle_radius_mm = 0.0;
    std::vector<FaceUpPixel> pixels;  // row-major, row 0 at -z (top of the picture)
    FaceUpTotals totals;

    const FaceUpPixel& at(int x, int y) const {
        return pixels[static_cast<std::size_t>(y) * resolution + x];
    }
};

// The stone's material supplies n(λ). Runs over every core (trace/parallel.hpp).
FaceUpAnalysis analyse_face_up(const Stone& stone, const FaceUpSettings& settings);

// The totals averaged over views, each view weighing the same (its settings' tilt replaced).
// Why: a single face-up view under a sky with sharp edges (the head's cone, the horizon)
// switches whole facets between lit and dark as an angle changes by a fraction of a degree,
// so light return against a cut angle is jagged; a viewer rocks the stone, and light
// performance grading looks at tilted views as well (Sasian et al. 2007, tilt views; GIA's
// observations were made with the stone tilted, Moses et al., Gems & Gemology 40(3), 2004).
FaceUpTotals tilt_averaged_totals(const Stone& stone, const FaceUpSettings& settings,
                                  const std::vector<ViewTilt>& views);

// Mean light return of the stone pixels whose radius / girdle radius lies in [r0, r1), and
// the number of them (0 gives 0).
double mean_light_return(const FaceUpAnalysis& analysis, double r0, double r1,
                         int* count = nullptr);

// Radial profile: `bins` equal rings over [0, 1) of the girdle radius, the mean of `value`
// over the stone pixels in each whose azimuth lies within `half_wedge_deg` of a direction in
// `azimuths_deg` (azimuth measured about +y from +x toward +z); every pixel when the list is
// empty. Empty rings give a negative value.
std::vector<double> radial_profile(const FaceUpAnalysis& analysis, int bins,
                                   float FaceUpPixel::*value,
                                   const std::vector<double>& azimuths_deg = {},
                                   double half_wedge_deg = 0.0);

}  // namespace gem
