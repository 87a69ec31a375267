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
    // The integral of the function's positive part over the visible range.
    double positive_total() const { return cumulative_.back(); }
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
    // The frames ranked by the radical inverse of their index in base 5; the frame of rank r
    // samples stratum (r + frames / 2) mod frames of each channel, so the first still frame
    // takes the middle of each channel's range, as near the moving picture's dominant
    // wavelengths as a stratum comes, and the next ones spread over it by fifths. Base 5 is
    // the Halton sequence's third dimension beside the sub-pixel offsets' 2 and 3
    // (HdrPicture::jitter_ndc): in base 2 a frame's wavelengths were a function of its
    // horizontal offset, each wavelength seen from one side of the pixel only, and a diamond's
    // still picture converged to ΔE00 3.2 from the spectral reference instead of 1.9
    // (bench_still_picture at 256 frames and depth 64, docs/accuracy.md).
    std::vector<int> by_inverse(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f) by_inverse[static_cast<std::size_t>(f)] = f;
    std::stable_sort(by_inverse.begin(), by_inverse.end(), [](int a, int b) {
        return radical_inverse(static_cast<unsigned>(a), 5) <
               radical_inverse(static_cast<unsigned>(b), 5);
    });
    const ChannelScale scales[3] = {ChannelScale(0), ChannelScale(1), ChannelScale(2)};
    const glm::dvec3 positive(scales[0].positive_total(), scales[1].positive_total(),
                              scales[2].positive_total());
    const glm::dvec3 whole = integrate_linear_srgb(kSpectrumMinNm, kSpectrumMaxNm);
    frames_.resize(static_cast<std::size_t>(frames));
    for (int channel = 0; channel < 3; ++channel) {
        for (int rank = 0; rank < frames; ++rank) {
            const int stratum = (rank + frames / 2) % frames;
            frames_[static_cast<std::size_t>(by_inverse[rank])].nm[channel] =
                scales[channel].wavelength_at((stratum + 0.5) / frames);
        }
    }
    // A channel is its positive part's mean (the channel's own trace, its strata being of
    // equal weight) less its negative lobe's mean, each by its share of the whole integral:
    // c = (P m+ - N m-) / (P - N).
    for (StillWavelengths& frame : frames_) {
        glm::dmat3 lobe_weight(0.0);  // [k][c]: trace k inside channel c's negative lobe
        glm::dvec3 lobe_sum(0.0);
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 cmf = xyz_to_linear_srgb(cie1931_xyz(frame.nm[k]));
            // The density the three channels' strata sample this wavelength with.
            const glm::dvec3 density = glm::max(cmf, glm::dvec3(0.0)) / positive;
            const glm::dvec3 w =
                glm::max(-cmf, glm::dvec3(0.0)) / (density.x + density.y + density.z);
            lobe_weight[k] = w;
            lobe_sum += w;
        }
        frame.mix = glm::dmat3(0.0);
        for (int c = 0; c < 3; ++c) {
            const double negative = positive[c] - whole[c];
            // No trace inside the lobe this frame: the channel is its positive part's mean.
            if (lobe_sum[c] <= 0.0) {
                frame.mix[c][c] = 1.0;
                continue;
            }
            frame.mix[c][c] = positive[c] / whole[c];
            for (int k = 0; k < 3; ++k) {
                frame.mix[k][c] -= negative / whole[c] * lobe_weight[k][c] / lobe_sum[c];
            }
        }
    }
}

}  // namespace gem
