// Rectangles of changed pixels (gpu/pixel_rect.hpp): affected_by() against every output texel's
// taps enumerated one by one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gpu/pixel_rect.hpp"

namespace gem::gpu {
namespace {

// Whether output texel j's taps read an input texel in [a, b), enumerated: the tap positions
// from reach_lo to reach_hi in steps of a quarter texel (the shaders' taps are whole texels
// apart), each bilinear, reading the two texels about it.
bool reads(int j, int a, int b, double scale, double reach_lo, double reach_hi) {
    const double centre = (j + 0.5) * scale;
    for (double o = reach_lo; o <= reach_hi + 1e-9; o += 0.25) {
        const double x = centre + o;
        const int left = static_cast<int>(std::floor(x - 0.5));
        for (int t : {left, left + 1}) {
            if (t >= a && t < b) return true;
        }
    }
    return false;
}

TEST(GpuPixelRect, AnOutputTexelThatReadsTheRegionIsInItsAffectedRectangle) {
    std::mt19937 random(7);
    struct Pass {
        double scale, lo, hi;
        int input, output;
    };
    // The glare's passes as they run at 1080p: down (scale 2, taps ±2), up from a level half
    // the size (±1), and the finish reading the top level at the picture's pixel centres.
    const Pass passes[] = {{2.0, -2.0, 2.0, 1920, 960},
                           {2.0, -2.0, 2.0, 135, 67},
                           {60.0 / 120.0, -1.0, 1.0, 60, 120},
                           {33.0 / 67.0, -1.0, 1.0, 33, 67},
                           {960.0 / 1920.0, 0.0, 0.0, 960, 1920}};
    for (const Pass& p : passes) {
        for (int trial = 0; trial < 40; ++trial) {
            const int a = std::uniform_int_distribution<int>(0, p.input - 1)(random);
            const int b = std::uniform_int_distribution<int>(a + 1, p.input)(random);
            const PixelRect in{a, 0, b, 1};
            const PixelRect out = affected_by(in, {p.scale, 1.0}, p.lo, p.hi, {p.output, 1});
            int first = -1, last = -1;
            for (int j = 0; j < p.output; ++j) {
                if (!reads(j, a, b, p.scale, p.lo, p.hi)) continue;
                if (first < 0) first = j;
                last = j;
                EXPECT_TRUE(j >= out.x0 && j < out.x1)
                    << "texel " << j << " reads [" << a << ", " << b << ") at scale " << p.scale
                    << " but lies outside [" << out.x0 << ", " << out.x1 << ")";
            }
            // Not the whole output for a small input: at most a texel or two to spare per side.
            ASSERT_GE(first, 0);
            EXPECT_LE(first - out.x0, 2);
            EXPECT_LE(out.x1 - 1 - last, 2);
        }
    }
}

TEST(GpuPixelRect, EveryInputTexelAnOutputRegionReadsIsInItsReadRectangle) {
    std::mt19937 random(11);
    struct Pass {
        double scale, lo, hi;
        int input, output;
    };
    // The glare's passes up (±1 texels of a level half the size) and the finish.
    const Pass passes[] = {{60.0 / 120.0, -1.0, 1.0, 60, 120},
                           {33.0 / 67.0, -1.0, 1.0, 33, 67},
                           {67.0 / 135.0, -1.0, 1.0, 67, 135},
                           {960.0 / 1920.0, 0.0, 0.0, 960, 1920},
                           {2.0, -2.0, 2.0, 135, 67}};
    for (const Pass& p : passes) {
        for (int trial = 0; trial < 40; ++trial) {
            const int a = std::uniform_int_distribution<int>(0, p.output - 1)(random);
            const int b = std::uniform_int_distribution<int>(a + 1, p.output)(random);
            const PixelRect in = read_by({a, 0, b, 1}, {p.scale, 1.0}, p.lo, p.hi, {p.input, 1});
            int first = -1, last = -1;
            for (int t = 0; t < p.input; ++t) {
                bool read = false;
                for (int j = a; j < b && !read; ++j) read = reads(j, t, t + 1, p.scale, p.lo, p.hi);
                if (!read) continue;
                if (first < 0) first = t;
                last = t;
                EXPECT_TRUE(t >= in.x0 && t < in.x1)
                    << "texel " << t << " is read by [" << a << ", " << b << ") at scale "
                    << p.scale << " but lies outside [" << in.x0 << ", " << in.x1 << ")";
            }
            ASSERT_GE(first, 0);
            EXPECT_LE(first - in.x0, 2);
            EXPECT_LE(in.x1 - 1 - last, 2);
        }
    }
}

TEST(GpuPixelRect, UnitedClampedAndIntersectedKeepThePixelsTheyShould) {
    const PixelRect a{10, 20, 30, 40}, b{25, 5, 60, 22};
    EXPECT_EQ(united(a, b), (PixelRect{10, 5, 60, 40}));
    EXPECT_EQ(united(a, PixelRect{}), a);
    EXPECT_EQ(united(PixelRect{}, b), b);
    EXPECT_EQ(clamped({-5, -5, 8, 300}, 100, 50), (PixelRect{0, 0, 8, 50}));
    EXPECT_TRUE(clamped({120, 0, 130, 10}, 100, 50).empty());
    EXPECT_EQ((PixelRect{2, 3, 12, 8}).area(), 50);
    // The pixels in both: x 25..30, y 20..22; apart, none.
    EXPECT_EQ(intersected(a, b), (PixelRect{25, 20, 30, 22}));
    EXPECT_TRUE(intersected(a, PixelRect{40, 0, 50, 10}).empty());
}

}  // namespace
}  // namespace gem::gpu
