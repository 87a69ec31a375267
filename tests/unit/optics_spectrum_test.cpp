// Spectral colour: the colour matching function fit against the published CIE 1931 table,
// the spectral sample weights, and the sRGB encoding (IEC 61966-2-1).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "optics/colour.hpp"
#include "optics/spectrum.hpp"

namespace gem {
namespace {

TEST(OpticsSpectrum, FlatSpectrumSumsToWhite) {
    for (int count : {1, 2, 3, 7, 8, 16, 31, 64, 350}) {
        for (double jitter : {0.0, 0.25, 0.5, 0.999}) {
            const SpectralSamples s = spectral_samples(count, jitter);
            ASSERT_EQ(s.size(), static_cast<std::size_t>(count));
            glm::dvec3 sum{0.0};
            for (const SpectralSample& sample : s) sum += sample.rgb_weight;
            EXPECT_NEAR(sum.x, 1.0, 1e-12) << count << " samples";
            EXPECT_NEAR(sum.y, 1.0, 1e-12) << count << " samples";
            EXPECT_NEAR(sum.z, 1.0, 1e-12) << count << " samples";
        }
    }
}

TEST(OpticsSpectrum, SamplesAreStratifiedOverTheVisibleRange) {
    const int count = 10;
    const double width = (730.0 - 380.0) / count;  // 35 nm strata
    for (double jitter : {0.0, 0.5, 0.9}) {
        const SpectralSamples s = spectral_samples(count, jitter);
        for (int i = 0; i < count; ++i) {
            EXPECT_NEAR(s[i].wavelength_nm, 380.0 + (i + jitter) * width, 1e-9);
        }
    }
}

TEST(OpticsSpectrum, SampleWeightsFollowTheirColour) {
    // With 7 strata of 50 nm: 430–480 is blue, 480–530 green, 630–680 red.
    const SpectralSamples s = spectral_samples(7);
    const glm::dvec3 blue = s[1].rgb_weight, green = s[2].rgb_weight, red = s[5].rgb_weight;
    EXPECT_GT(blue.z, blue.x);
    EXPECT_GT(blue.z, blue.y);
    EXPECT_GT(green.y, green.x);
    EXPECT_GT(green.y, green.z);
    EXPECT_GT(red.x, red.y);
    EXPECT_GT(red.x, red.z);
}

// The frames of a still view (StillSpectrum) against each channel's spectral integral taken
// directly, a 0.01 nm midpoint sum of the linear-sRGB colour matching functions, negative
// lobes and all, each channel scaled so a flat spectrum gives 1: as the CPU reference's
// wavelength samples weigh a spectrum (spectral_samples).
glm::dvec3 channel_integrals(glm::dvec3 (*colour)(double)) {
    glm::dvec3 sum{0.0}, weight{0.0};
    for (double nm = kSpectrumMinNm + 0.005; nm < kSpectrumMaxNm; nm += 0.01) {
        const glm::dvec3 cmf = xyz_to_linear_srgb(cie1931_xyz(nm));
        sum += cmf * colour(nm);
        weight += cmf;
    }
    return sum / weight;
}

// Each frame's traces (`colour` at each of its wavelengths) mixed as the frame says, averaged.
glm::dvec3 still_mean(const StillSpectrum& still, glm::dvec3 (*colour)(double)) {
    glm::dvec3 sum{0.0};
    for (int f = 0; f < still.frames(); ++f) {
        const StillWavelengths& frame = still.frame(f);
        for (int k = 0; k < 3; ++k) sum += frame.mix[k] * colour(frame.nm[k]);
    }
    return sum / static_cast<double>(still.frames());
}

glm::dvec3 smooth(double nm) {
    return {1.0 + 0.5 * std::sin(nm / 23.0), 1.0 + 0.5 * std::cos(nm / 31.0), nm / 700.0};
}
// A prism's exit: one colour below 520 nm, another above (a ray that leaves by one facet at
// short wavelengths and another at long ones).
glm::dvec3 step(double nm) {
    return nm < 520.0 ? glm::dvec3(0.2, 0.9, 3.0) : glm::dvec3(2.0, 0.1, 0.4);
}
// Fire: only the long or only the short wavelengths reach a light.
glm::dvec3 long_only(double nm) {
    return glm::dvec3(nm > 560.0 ? 1.0 : 0.0);
}
glm::dvec3 short_only(double nm) {
    return glm::dvec3(nm < 500.0 ? 1.0 : 0.0);
}

TEST(OpticsSpectrum, StillFramesConvergeToEachChannelsSpectralIntegral) {
    // The negative lobes are a per-frame ratio estimate (spectrum.hpp): a few hundredths off
    // on these, at any count of frames. Leaving the lobes out is off by 0.1 to 0.4 on each
    // (red of long_only: 0.94 against 1.30).
    constexpr double kTolerance = 0.06;
    for (const int frames : {16, 256}) {
        const StillSpectrum still(frames);
        ASSERT_EQ(still.frames(), frames);
        for (const auto colour : {smooth, step, long_only, short_only}) {
            const glm::dvec3 a = still_mean(still, colour), b = channel_integrals(colour);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(a[c], b[c], kTolerance) << frames << " frames, channel " << c;
            }
        }
    }
    // The negative lobes count: red light only above 560 nm is more red than the positive
    // part's mean, and blue takes a little away.
    const glm::dvec3 b = channel_integrals(long_only);
    EXPECT_GT(b.x, 1.2);
    EXPECT_LT(b.z, -0.03);
}

TEST(OpticsSpectrum, EveryStillFrameIsWhiteBalanced) {
    // A flat spectrum gives every channel 1 in every frame, not only on average: each frame
    // may fall on an edge differently.
    for (const int frames : {1, 16, 256}) {
        const StillSpectrum still(frames);
        for (int f = 0; f < frames; ++f) {
            const glm::dmat3& mix = still.frame(f).mix;
            const glm::dvec3 flat = mix[0] + mix[1] + mix[2];
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(flat[c], 1.0, 1e-12) << "frame " << f;
            // A channel's own trace weighs most.
            for (int c = 0; c < 3; ++c) EXPECT_GE(mix[c][c], 1.0) << "frame " << f;
        }
    }
}

TEST(OpticsSpectrum, StillFramesStratifyEachChannel) {
    const StillSpectrum still(16);
    std::vector<double> by_channel[3];
    for (int f = 0; f < still.frames(); ++f) {
        for (int c = 0; c < 3; ++c) by_channel[c].push_back(still.frame(f).nm[c]);
    }
    // Red where red is, blue where blue is: each channel's strata lie where its function does.
    const auto mid = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    EXPECT_GT(mid(by_channel[0]), 580.0);
    EXPECT_NEAR(mid(by_channel[1]), 550.0, 25.0);
    EXPECT_LT(mid(by_channel[2]), 480.0);
    for (auto& v : by_channel) {
        std::sort(v.begin(), v.end());
        for (std::size_t i = 1; i < v.size(); ++i) EXPECT_GT(v[i], v[i - 1]);  // one a stratum
    }
    // The first frame takes each channel's middle stratum, near its dominant wavelength
    // (612, 549, 465 nm); the first five fall in five different fifths of the strata.
    EXPECT_NEAR(still.frame(0).nm.x, 612.0, 25.0);
    EXPECT_NEAR(still.frame(0).nm.y, 549.0, 25.0);
    EXPECT_NEAR(still.frame(0).nm.z, 465.0, 25.0);
    for (int c = 0; c < 3; ++c) {
        std::vector<bool> fifth_taken(5, false);
        for (int f = 0; f < 5; ++f) {
            const auto rank =
                std::find(by_channel[c].begin(), by_channel[c].end(), still.frame(f).nm[c]) -
                by_channel[c].begin();
            const std::size_t fifth = static_cast<std::size_t>(rank * 5 / 16);
            EXPECT_FALSE(fifth_taken[fifth]) << "channel " << c << ", frame " << f;
            fifth_taken[fifth] = true;
        }
    }
}

TEST(OpticsSpectrum, ColourMatchingFitAgreesWithCieTable) {
    // CIE 1931 2° observer, CIE 15:2004 table (5 nm steps). A sum of a few Gaussian lobes
    // cannot match the table exactly; 0.02 (about 2 % of the peaks) allows that, while a
    // wrong lobe coefficient moves the values by more.
    struct Row {
        double nm, x, y, z;
    };
    const Row table[] = {
        {445.0, 0.34806, 0.02980, 1.78260}, {450.0, 0.33620, 0.03800, 1.77211},
        {500.0, 0.00490, 0.32300, 0.27200}, {555.0, 0.51205, 1.00000, 0.00575},
        {600.0, 1.06220, 0.63100, 0.00080}, {650.0, 0.28350, 0.10700, 0.00000},
        {700.0, 0.01136, 0.00410, 0.00000},
    };
    for (const Row& row : table) {
        const glm::dvec3 cmf = cie1931_xyz(row.nm);
        EXPECT_NEAR(cmf.x, row.x, 0.02) << row.nm << " nm";
        EXPECT_NEAR(cmf.y, row.y, 0.02) << row.nm << " nm";
        EXPECT_NEAR(cmf.z, row.z, 0.02) << row.nm << " nm";
    }
}

TEST(OpticsSpectrum, ColourMatchingPeaksWhereCieHasThem) {
    // CIE table: ȳ peaks at 555 nm with 1.0, x̄ at 600 nm with 1.0622, z̄ at 445 nm with 1.7826.
    glm::dvec3 best{0.0}, where{0.0};
    for (double nm = 380.0; nm <= 780.0; nm += 0.5) {
        const glm::dvec3 v = cie1931_xyz(nm);
        for (int c = 0; c < 3; ++c) {
            if (v[c] > best[c]) best[c] = v[c], where[c] = nm;
        }
    }
    EXPECT_NEAR(where.y, 555.0, 5.0);
    EXPECT_NEAR(best.y, 1.0, 0.02);
    EXPECT_NEAR(where.x, 600.0, 5.0);
    EXPECT_NEAR(best.x, 1.06, 0.02);
    EXPECT_NEAR(where.z, 445.0, 5.0);
    EXPECT_NEAR(best.z, 1.78, 0.02);
}

TEST(OpticsColour, D65WhiteIsSrgbWhite) {
    // D65 white point, XYZ (0.9505, 1.0000, 1.0890) (CIE 15), maps to linear sRGB (1, 1, 1)
    // to the precision of the standard's 4-decimal matrix.
    const glm::dvec3 rgb = xyz_to_linear_srgb({0.9505, 1.0, 1.0890});
    EXPECT_NEAR(rgb.x, 1.0, 1e-3);
    EXPECT_NEAR(rgb.y, 1.0, 1e-3);
    EXPECT_NEAR(rgb.z, 1.0, 1e-3);
    // The sRGB red primary, chromaticity (0.64, 0.33) with Y = 0.2126 (IEC 61966-2-1),
    // comes out as pure red of 1.
    const double Y = 0.2126, x = 0.64, y = 0.33;
    const glm::dvec3 red = xyz_to_linear_srgb({x * Y / y, Y, (1.0 - x - y) * Y / y});
    EXPECT_NEAR(red.x, 1.0, 2e-3);
    EXPECT_NEAR(red.y, 0.0, 2e-3);
    EXPECT_NEAR(red.z, 0.0, 2e-3);
}

TEST(OpticsColour, SrgbKnownValues) {
    // 0.5 linear: 1.055 · 0.5^(1/2.4) − 0.055 = 0.7354 → 187.5 → code 188 (±1).
    EXPECT_NEAR(static_cast<int>(linear_to_srgb8(0.5)), 188, 1);
    EXPECT_EQ(linear_to_srgb8(0.0), 0);
    EXPECT_EQ(linear_to_srgb8(1.0), 255);
    EXPECT_EQ(linear_to_srgb8(2.0), 255);  // clamped
    EXPECT_EQ(linear_to_srgb8(-1.0), 0);   // clamped
    // Code 128 is 0.2158605 linear (((128/255 + 0.055)/1.055)^2.4); 0.18 grey is 118.
    EXPECT_NEAR(srgb8_to_linear(128), 0.2158605, 1e-6);
    EXPECT_EQ(linear_to_srgb8(0.18), 118);
    // The two pieces meet: 0.0031308 · 12.92 = 0.04045.
    EXPECT_NEAR(srgb_encode(0.0031308), 0.04045, 1e-5);
    EXPECT_NEAR(srgb_decode(0.04045), 0.0031308, 1e-6);
    EXPECT_NEAR(srgb_encode(0.0031309), 0.04045, 1e-5);
}

TEST(OpticsColour, SrgbRoundTrips) {
    for (int code = 0; code < 256; ++code) {
        const auto c = static_cast<std::uint8_t>(code);
        EXPECT_EQ(linear_to_srgb8(srgb8_to_linear(c)), c);
    }
    for (int i = 0; i <= 1000; ++i) {
        const double v = i / 1000.0;
        EXPECT_NEAR(srgb_decode(srgb_encode(v)), v, 1e-12);
        EXPECT_NEAR(srgb_encode(srgb_decode(v)), v, 1e-12);
    }
    const glm::u8vec3 rgb{12, 128, 250};
    EXPECT_EQ(linear_to_srgb8(srgb8_to_linear(rgb)), rgb);
}

}  // namespace
}  // namespace gem
