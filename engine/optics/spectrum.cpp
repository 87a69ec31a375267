#include "optics/spectrum.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "optics/colour.hpp"
#include "util/radical_inverse.hpp"

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

// Where the cumulative positive part of one linear-sRGB colour matching function over the
// visible range reaches `share` of its whole, by the same 1 nm midpoint steps, linear inside
// a step.
class ChannelScale {
  public:
    explicit ChannelScale(int channel) {
        const int steps =
            static_cast<int>(std::ceil((kSpectrumMaxNm - kSpectrumMinNm) / kIntegrationStepNm));
        step_ = (kSpectrumMaxNm - kSpectrumMinNm) / steps;
        cumulative_.push_back(0.0);
        for (int i = 0; i < steps; ++i) {
            const glm::dvec3 rgb =
                xyz_to_linear_srgb(cie1931_xyz(kSpectrumMinNm + (i + 0.5) * step_));
            cumulative_.push_back(cumulative_.back() + std::max(rgb[channel], 0.0) * step_);
        }
    }
    double wavelength_at(double share) const {
        const double mass = share * cumulative_.back();
        const auto above = std::upper_bound(cumulative_.begin(), cumulative_.end(), mass);
        const auto i = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
            above - cumulative_.begin(), 1, static_cast<std::ptrdiff_t>(cumulative_.size()) - 1));
        const double inside =
            (mass - cumulative_[i - 1]) / std::max(cumulative_[i] - cumulative_[i - 1], 1e-300);
        return kSpectrumMinNm + (static_cast<double>(i - 1) + std::clamp(inside, 0.0, 1.0)) * step_;
    }

  private:
    double step_ = 1.0;
    std::vector<double> cumulative_;
};

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

StillSpectrum::StillSpectrum(int frames) {
    assert(frames >= 1);
    // The frames ranked by the radical inverse of their index; the frame of rank r samples
    // stratum (r + frames / 2) mod frames of each channel, so the first still frame takes the
    // middle of each channel's range, as near the moving picture's dominant wavelengths as a
    // stratum comes, and the next ones the middles of its halves, quarters, ...
    std::vector<int> by_inverse(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f) by_inverse[static_cast<std::size_t>(f)] = f;
    std::stable_sort(by_inverse.begin(), by_inverse.end(), [](int a, int b) {
        return radical_inverse(static_cast<unsigned>(a), 2) <
               radical_inverse(static_cast<unsigned>(b), 2);
    });
    frames_.resize(static_cast<std::size_t>(frames));
    for (int channel = 0; channel < 3; ++channel) {
        const ChannelScale scale(channel);
        for (int rank = 0; rank < frames; ++rank) {
            const int stratum = (rank + frames / 2) % frames;
            frames_[static_cast<std::size_t>(by_inverse[rank])][channel] =
                scale.wavelength_at((stratum + 0.5) / frames);
        }
    }
}

}  // namespace gem
