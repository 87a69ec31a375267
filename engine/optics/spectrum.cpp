#include "optics/spectrum.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "optics/colour.hpp"

namespace gem {

namespace {

// Wyman, Sloan & Shirley's piecewise Gaussian: a different width left and right of the mean.
double lobe(double wavelength_nm, double mean, double width_below, double width_above) {
    const double t = (wavelength_nm - mean) / (wavelength_nm < mean ? width_below : width_above);
    return std::exp(-0.5 * t * t);
}

// Stratum integrals use midpoint steps of at most 1 nm: the functions vary over tens of nm,
// so the weights are accurate to well below what an 8-bit output can show.
constexpr double kIntegrationStepNm = 1.0;

glm::dvec3 integrate_linear_srgb(double from_nm, double to_nm) {
    const int steps =
        std::max(1, static_cast<int>(std::ceil((to_nm - from_nm) / kIntegrationStepNm)));
    const double step = (to_nm - from_nm) / steps;
    glm::dvec3 sum{0.0};
    for (int i = 0; i < steps; ++i) {
        sum += xyz_to_linear_srgb(cie1931_xyz(from_nm + (i + 0.5) * step));
    }
    return sum * step;
}

}  // namespace

glm::dvec3 cie1931_xyz(double wavelength_nm) {
    const double l = wavelength_nm;
    return {1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) -
                0.065 * lobe(l, 501.1, 20.4, 26.2),
            0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1),
            1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8)};
}

SpectralSamples spectral_samples(int count, double jitter) {
    assert(count >= 1);
    assert(jitter >= 0.0 && jitter < 1.0);
    const double width = (kSpectrumMaxNm - kSpectrumMinNm) / count;
    SpectralSamples out;
    out.samples.resize(static_cast<std::size_t>(count));
    glm::dvec3 total{0.0};
    for (int i = 0; i < count; ++i) {
        const double from = kSpectrumMinNm + i * width;
        SpectralSample& s = out.samples[static_cast<std::size_t>(i)];
        s.wavelength_nm = from + jitter * width;
        s.rgb_weight = integrate_linear_srgb(from, from + width);
        total += s.rgb_weight;
    }
    // Equal-energy white is not sRGB's D65 white, so each channel is scaled on its own; this
    // is a white balance to illuminant E, which keeps grey objects grey.
    for (SpectralSample& s : out.samples) s.rgb_weight /= total;
    return out;
}

}  // namespace gem
