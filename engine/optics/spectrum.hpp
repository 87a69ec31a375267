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

// The wavelengths of a still view's frames: each frame traces one wavelength per colour
// channel, and over the frames each channel's wavelengths stratify the spectrum by that
// channel's colour matching function, so the mean of the frames is each channel's spectral
// integral (where exact fire samples each channel at one dominant wavelength,
// gpu/channel_wavelengths.hpp). Each frame takes the middle of one stratum of equal weight per
// channel, in radical-inverse order from the middle one (1/2, 0, 3/4, 1/4, ...), so the first
// few frames already cover the spectrum evenly.
//
// A wavelength counts for its own channel only: every frame is white balanced, so a frame's
// sub-pixel offset and its wavelengths do not mix (weights that differed from frame to frame
// would tint the edges the offsets resolve: measured, ΔE00 1.2 on average on a diamond without
// dispersion). The linear-sRGB functions' negative lobes are left out: they take a little from
// a channel where light of another colour mixes in, and otherwise only push a colour outside
// the gamut, which the display clips.
class StillSpectrum {
  public:
    // frames ≥ 1.
    explicit StillSpectrum(int frames);
    int frames() const { return static_cast<int>(frames_.size()); }
    // The wavelengths (nm) of frame `index` (0 ≤ index < frames()): red's, green's, blue's.
    const glm::dvec3& frame(int index) const { return frames_[static_cast<std::size_t>(index)]; }

  private:
    std::vector<glm::dvec3> frames_;
};

}  // namespace gem
