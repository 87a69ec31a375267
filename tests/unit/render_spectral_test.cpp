// Spectral rendering: with a constant index every wavelength follows the same path, and the
// spectral weights add up to white, so the image must equal the RGB render.
#include <cmath>

#include <gtest/gtest.h>

#include "cpu/reference_render.hpp"
#include "render_test_stones.hpp"

namespace gem {
namespace {

RenderSettings oblique(bool spectral) {
    RenderSettings s;
    s.width = 20;
    s.height = 20;
    s.samples_per_pixel = 2;
    s.camera = {.azimuth_deg = 30.0, .elevation_deg = 25.0, .roll_deg = 10.0};
    s.spectral = spectral;
    s.spectral_samples = 8;
    return s;
}

TEST(RenderSpectral, ConstantIndexEqualsTheRgbRender) {
    const Stone cube = render_test::cube(1.0, 1.6, {0.1, 0.2, 0.3});
    const Environment studio = Environment::studio();
    Result<Image> rgb = render_reference(cube, studio, oblique(false));
    Result<Image> spectral = render_reference(cube, studio, oblique(true));
    ASSERT_TRUE(rgb.ok() && spectral.ok());
    double largest = 0.0;
    for (std::size_t i = 0; i < rgb.value().pixels.size(); ++i) {
        for (int c = 0; c < 4; ++c) {
            const double a = rgb.value().pixels[i][c];
            const double b = spectral.value().pixels[i][c];
            EXPECT_NEAR(a, b, 1e-5 * std::max(1.0, std::abs(a))) << "pixel " << i;
            largest = std::max(largest, a);
        }
    }
    EXPECT_GT(largest, 0.1);  // the comparison saw something lit
}

TEST(RenderSpectral, DispersionChangesTheImage) {
    // The same stone with a strongly dispersive index: the wavelengths part ways, so the
    // comparison above is able to tell.
    Stone cube = render_test::cube(1.0, 1.6, {0.1, 0.2, 0.3});
    cube.material.dispersion = Dispersion::cauchy_from_nd(1.6, 0.08);
    const Environment studio = Environment::studio();
    Result<Image> rgb = render_reference(cube, studio, oblique(false));
    Result<Image> spectral = render_reference(cube, studio, oblique(true));
    ASSERT_TRUE(rgb.ok() && spectral.ok());
    double largest_difference = 0.0;
    for (std::size_t i = 0; i < rgb.value().pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            largest_difference = std::max(
                largest_difference,
                double(std::abs(rgb.value().pixels[i][c] - spectral.value().pixels[i][c])));
        }
    }
    EXPECT_GT(largest_difference, 1e-3);
}

}  // namespace
}  // namespace gem
