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

// One frame of a still view: the wavelengths it traces, one per colour channel, and what each
// trace adds to each channel.
struct StillWavelengths {
    glm::dvec3 nm{0.0};  // red's, green's, blue's trace
    // Column k: the share of trace k in each channel (a channel's traces are its colour, the
    // same channel of the others' colours, times these). Each channel's shares add up to 1.
    glm::dmat3 mix{1.0};
};

// The wavelengths of a still view's frames, so that the mean of the frames is each channel's
// spectral integral, negative lobes included (where exact fire samples each channel at one
// dominant wavelength, gpu/channel_wavelengths.hpp). Each frame traces one wavelength per
// channel; over the frames each channel's wavelengths stratify its colour matching function's
// positive part, the middle of one stratum of equal weight per frame, in radical-inverse
// order (base 5) from the middle one, so the first few frames already cover the spectrum
// evenly, and independently of the frames' sub-pixel offsets (bases 2 and 3).
//
// A channel's negative lobe (linear sRGB's functions dip below zero where another primary's
// colour is: red between about 460 and 550 nm) is the frame's three traces weighted by how
// far each falls inside it, against how densely the three channels' strata sample there
// (balance heuristic), divided by those weights' sum: a mean of that channel's light over
// the lobe. Without it a channel is off by 10-30 % wherever light is not white (red of light
// above 560 nm only: 0.94 for 1.30), and a diamond's still picture, converged at depth 64, is
// ΔE00 0.5 further from the spectral reference (bench_still_picture).
//
// Every frame is white balanced: a flat spectrum gives each channel exactly 1, so a frame's
// sub-pixel offset and its wavelengths do not mix (weights that differed from frame to frame
// would tint the edges the offsets resolve: measured, ΔE00 1.2 on average on a diamond without
// dispersion). The division makes the lobe's share a ratio estimate: a few per cent off a
// smooth spectrum's integral, where leaving the lobe out is off by up to a third.
class StillSpectrum {
  public:
    // frames ≥ 1.
    explicit StillSpectrum(int frames);
    int frames() const { return static_cast<int>(frames_.size()); }
    const StillWavelengths& frame(int index) const {
        return frames_[static_cast<std::size_t>(index)];
    }

  private:
    std::vector<StillWavelengths> frames_;
};

}  // namespace gem
