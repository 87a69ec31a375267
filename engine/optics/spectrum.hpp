#pragma once
// Spectral colour for dispersion ("fire"): the CIE 1931 colour matching functions and a set
// of wavelength samples whose linear-RGB weights add up to white.

#include <array>
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
// integral (as exact fire samples each channel at one dominant wavelength, kChannelNm). The
// k-th of `frames` frames takes the middle of the stratum holding (r(k) + 1/2) / frames of the
// channel's weight, r(k) its rank in radical-inverse order (0, 1/2, 1/4, 3/4, ...), so the
// first few frames already cover the spectrum evenly. A sample counts for its own channel
// only, with weight 1: every frame is white balanced, so a frame's sub-pixel offset and its
// wavelengths do not mix (weights that differ from frame to frame would tint the edges the
// offsets resolve). The linear-sRGB functions' negative lobes are left out: they only
// subtract where the display clips to black anyway (a spectral colour outside the gamut).
inline constexpr int kMaxWavelengthsPerFrame = 4;

struct FrameSpectrum {
    int count = 0;
    std::array<SpectralSample, kMaxWavelengthsPerFrame> samples{};  // the first `count`
};

class StillSpectrum {
  public:
    // frames ≥ 1; three wavelengths a frame, one per channel.
    explicit StillSpectrum(int frames);
    int frames() const { return static_cast<int>(frames_.size()); }
    int per_frame() const { return frames_.front().count; }
    // Frame `index`, 0 ≤ index < frames().
    const FrameSpectrum& frame(int index) const { return frames_[static_cast<std::size_t>(index)]; }

  private:
    std::vector<FrameSpectrum> frames_;
};

}  // namespace gem
