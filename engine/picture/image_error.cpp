// Image error as a person sees it: 8-bit sRGB PSNR and CIEDE2000 through Little CMS.
#include "picture/image_error.hpp"

#include <lcms2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "optics/colour.hpp"

namespace gem {

namespace {

// The D65 white as the matrix below maps RGB (1, 1, 1): its row sums, so white has a = b = 0.
constexpr cmsCIEXYZ kD65{0.9505, 1.0, 1.0890};

// Linear sRGB to XYZ, IEC 61966-2-1 (the inverse of optics/colour.cpp's matrix).
glm::dvec3 linear_srgb_to_xyz(const glm::dvec3& c) {
    return {0.4124 * c.x + 0.3576 * c.y + 0.1805 * c.z, 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z,
            0.0193 * c.x + 0.1192 * c.y + 0.9505 * c.z};
}

// A lookup of the 256 sRGB codes to linear light, so a 1080p image is not 6 M pow() calls.
const std::array<double, 256>& decode_table() {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgb8_to_linear(static_cast<std::uint8_t>(i));
        return t;
    }();
    return table;
}

Lab lab_of_codes(const std::uint8_t* rgb) {
    const auto& lin = decode_table();
    const glm::dvec3 xyz = linear_srgb_to_xyz({lin[rgb[0]], lin[rgb[1]], lin[rgb[2]]});
    const cmsCIEXYZ in{xyz.x, xyz.y, xyz.z};
    cmsCIELab out;
    cmsXYZ2Lab(&kD65, &out, &in);
    return {out.L, out.a, out.b};
}

bool is_stone(const std::uint8_t* rgba) {
    return rgba[3] >= 128;
}

}  // namespace

Lab srgb8_to_lab(unsigned char r, unsigned char g, unsigned char b) {
    const std::uint8_t rgb[3] = {r, g, b};
    return lab_of_codes(rgb);
}

double ciede2000(const Lab& x, const Lab& y) {
    const cmsCIELab a{x.l, x.a, x.b};
    const cmsCIELab b{y.l, y.a, y.b};
    // kL = kC = kH = 1: the reference viewing conditions of CIE 142-2001.
    return cmsCIE2000DeltaE(&a, &b, 1.0, 1.0, 1.0);
}

std::vector<float> delta_e_map(const Image& test, const Image& reference) {
    if (test.width != reference.width || test.height != reference.height) return {};
    const std::vector<std::uint8_t> x = to_srgb8(test, 4);
    const std::vector<std::uint8_t> y = to_srgb8(reference, 4);
    std::vector<float> map(test.pixels.size());
    for (std::size_t p = 0; p < map.size(); ++p) {
        const std::uint8_t* a = &x[p * 4];
        const std::uint8_t* b = &y[p * 4];
        const bool same = a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
        map[p] = same ? 0.0f : static_cast<float>(ciede2000(lab_of_codes(a), lab_of_codes(b)));
    }
    return map;
}

Result<ImageError> compare_images(const Image& test, const Image& reference,
                                  const ErrorOptions& options) {
    if (test.width != reference.width || test.height != reference.height)
        return Error{"compare_images: sizes differ (" + std::to_string(test.width) + "×" +
                     std::to_string(test.height) + " against " + std::to_string(reference.width) +
                     "×" + std::to_string(reference.height) + ")"};
    const std::vector<std::uint8_t> x = to_srgb8(test, 4);
    const std::vector<std::uint8_t> y = to_srgb8(reference, 4);
    const std::vector<float> map = delta_e_map(test, reference);

    std::vector<float> compared;
    compared.reserve(map.size());
    double squared = 0.0;
    for (std::size_t p = 0; p < map.size(); ++p) {
        if (options.only_stone && !is_stone(&x[p * 4]) && !is_stone(&y[p * 4])) continue;
        for (int c = 0; c < 3; ++c) {
            const double d = double(x[p * 4 + c]) - double(y[p * 4 + c]);
            squared += d * d;
        }
        compared.push_back(map[p]);
    }
    if (compared.empty()) return Error{"compare_images: no pixel to compare"};

    ImageError e;
    e.pixels = compared.size();
    const double mse = squared / (3.0 * static_cast<double>(compared.size()));
    e.psnr_db = mse == 0.0 ? std::numeric_limits<double>::infinity()
                           : 10.0 * std::log10(255.0 * 255.0 / mse);
    double sum = 0.0;
    std::size_t visible = 0;
    for (float d : compared) {
        sum += d;
        if (d > options.visible_delta_e) ++visible;
    }
    e.delta_e_mean = sum / static_cast<double>(compared.size());
    e.share_visible = static_cast<double>(visible) / static_cast<double>(compared.size());
    // Nearest rank: the smallest value with at least 99 % of the pixels at or below it.
    const std::size_t rank =
        static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(compared.size()))) - 1;
    std::nth_element(compared.begin(), compared.begin() + static_cast<std::ptrdiff_t>(rank),
                     compared.end());
    e.delta_e_p99 = compared[rank];
    e.delta_e_max = *std::max_element(compared.begin(), compared.end());
    return e;
}

Image heat_map(const std::vector<float>& delta_e, int width, int height, float full_scale) {
    Image out(width, height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    if (delta_e.size() != out.pixels.size() || full_scale <= 0.0f) return out;
    for (std::size_t p = 0; p < delta_e.size(); ++p) {
        // Black → red → yellow → white in thirds of full scale, in display (sRGB) terms.
        const float t = std::clamp(delta_e[p] / full_scale, 0.0f, 1.0f) * 3.0f;
        const glm::vec3 srgb(std::min(t, 1.0f), std::clamp(t - 1.0f, 0.0f, 1.0f),
                             std::clamp(t - 2.0f, 0.0f, 1.0f));
        out.pixels[p] = glm::vec4(static_cast<float>(srgb_decode(srgb.x)),
                                  static_cast<float>(srgb_decode(srgb.y)),
                                  static_cast<float>(srgb_decode(srgb.z)), 1.0f);
    }
    return out;
}

}  // namespace gem
