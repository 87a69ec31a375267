#include "optics/colour.hpp"

#include <algorithm>
#include <cmath>

namespace gem {

glm::dvec3 xyz_to_linear_srgb(const glm::dvec3& xyz) {
    // IEC 61966-2-1:1999 §5.2, the matrix as printed in the standard (4 decimals).
    return {3.2406 * xyz.x - 1.5372 * xyz.y - 0.4986 * xyz.z,
            -0.9689 * xyz.x + 1.8758 * xyz.y + 0.0415 * xyz.z,
            0.0557 * xyz.x - 0.2040 * xyz.y + 1.0570 * xyz.z};
}

// Break points and slopes from IEC 61966-2-1:1999 §5.2–5.3: a linear toe below 0.0031308
// (encoded 0.04045), a 1/2.4 power with offset 0.055 above.
double srgb_encode(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    if (c <= 0.0031308) return 12.92 * c;
    return 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double encoded) {
    const double c = std::clamp(encoded, 0.0, 1.0);
    if (c <= 0.04045) return c / 12.92;
    return std::pow((c + 0.055) / 1.055, 2.4);
}

std::uint8_t linear_to_srgb8(double linear) {
    return static_cast<std::uint8_t>(std::lround(srgb_encode(linear) * 255.0));
}

double srgb8_to_linear(std::uint8_t code) {
    return srgb_decode(code / 255.0);
}

glm::u8vec3 linear_to_srgb8(const glm::dvec3& linear) {
    return {linear_to_srgb8(linear.x), linear_to_srgb8(linear.y), linear_to_srgb8(linear.z)};
}

glm::dvec3 srgb8_to_linear(const glm::u8vec3& code) {
    return {srgb8_to_linear(code.x), srgb8_to_linear(code.y), srgb8_to_linear(code.z)};
}

}  // namespace gem
