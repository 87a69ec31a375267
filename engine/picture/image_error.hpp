#pragma once
// How far an image is from a reference, as a person would see it: both are taken to 8-bit
// sRGB (what the display shows), then compared pixel by pixel as PSNR over the RGB codes and
// as the CIEDE2000 colour difference ΔE00 (computed by Little CMS, from CIELAB with a D65
// white). The accuracy benchmark, the failure-mode tests and `gemtables build --budget` all
// measure error with this one definition.

#include <cstddef>
#include <vector>

#include "picture/image.hpp"
#include "util/result.hpp"

namespace gem {

// ΔE00 above which a difference counts as visible. Mokrzycki and Tatol, "Colour difference
// ΔE — a survey" (Machine Graphics & Vision 20(4), 2011), grade 1 < ΔE < 2 as seen only by an
// experienced observer and 2 < ΔE < 3.5 as seen by an inexperienced one: a shopper is the
// latter.
inline constexpr double kVisibleDeltaE = 2.0;

struct ErrorOptions {
    // Compare only pixels where either image has alpha > 0.5 (the stone), not the background.
    bool only_stone = false;
    double visible_delta_e = kVisibleDeltaE;
};

struct ImageError {
    double psnr_db = 0.0;       // infinity when the 8-bit images are identical
    double delta_e_mean = 0.0;  // CIEDE2000, mean over the compared pixels
    double delta_e_p99 = 0.0;   // its 99th percentile (nearest rank)
    double delta_e_max = 0.0;
    double share_visible = 0.0;  // share of compared pixels with ΔE00 > visible_delta_e
    std::size_t pixels = 0;      // pixels compared
};

// Errors: images of different sizes, or no pixel to compare.
Result<ImageError> compare_images(const Image& test, const Image& reference,
                                  const ErrorOptions& options = {});

// ΔE00 of every pixel (row-major, like Image::pixels); an empty vector for different sizes.
std::vector<float> delta_e_map(const Image& test, const Image& reference);

// A heat map of `delta_e` (width × height): black at 0, through red and yellow to white at
// `full_scale`, for the docs' error pictures.
Image heat_map(const std::vector<float>& delta_e, int width, int height, float full_scale);

// CIELAB (D65 white) of a linear sRGB colour after 8-bit sRGB quantisation, and ΔE00 of two
// CIELAB colours: exposed so the tests can check them against published values.
struct Lab {
    double l = 0.0, a = 0.0, b = 0.0;
};
Lab srgb8_to_lab(unsigned char r, unsigned char g, unsigned char b);
double ciede2000(const Lab& x, const Lab& y);

}  // namespace gem
