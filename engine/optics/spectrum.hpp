#pragma once
// Spectral colour for dispersion ("fire"): the CIE 1931 colour matching functions and a set
// of wavelength samples whose linear-RGB weights add up to white.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace gem {

// The visible range sampled for rendering (nm). Outside it the CIE 1931 functions are below
// 0.4 % of their peaks (CIE 15 table).
inline constexpr double kSpectrumMinNm = 380.0;
inline constexpr double kSpectrumMaxNm = 730.0;

// CIE 1931 2° colour matching functions (x̄, ȳ, z̄) at a wavelength in nm, from the
// multi-lobe analytic fit of Wyman, Sloan & Shirley, "Simple Analytic Approximations to the
// CIE XYZ Color Matching Functions", JCGT 2(2), 2013.
glm::dvec3 cie1931_xyz(double wavelength_nm);

struct SpectralSample {
    double wavelength_nm = 0.0;  // where the refractive index is evaluated
    glm::dvec3 rgb_weight{0.0};  // linear-RGB share of this sample; may be negative
};

// Wavelength samples, one per equal-width stratum of [kSpectrumMinNm, kSpectrumMaxNm], in
// increasing order. Each weight is the stratum's integral of the colour matching functions
// in linear sRGB, scaled per channel so that the weights of a flat (equal-energy) spectrum
// add up to exactly (1, 1, 1): a render with no dispersion is the same spectral or not.
struct SpectralSamples {
    std::vector<SpectralSample> samples;

    std::size_t size() const { return samples.size(); }
    const SpectralSample& operator[](std::size_t i) const { return samples[i]; }
    auto begin() const { return samples.begin(); }
    auto end() const { return samples.end(); }
};

// `count` strata (≥ 1); `jitter` in [0, 1) places each wavelength inside its stratum (0.5:
// the middle). Vary the jitter from frame to frame to trade banding for noise; the weights
// do not depend on it.
SpectralSamples spectral_samples(int count, double jitter = 0.5);

}  // namespace gem
