#pragma once
// Colour encodings: CIE XYZ to linear sRGB, and the sRGB transfer function between linear
// values and 8-bit output (IEC 61966-2-1:1999). Linear RGB is used everywhere inside.

#include <cstdint>

#include <glm/glm.hpp>

namespace gem {

// XYZ (Y = 1 for the white point) to linear sRGB primaries, D65 white. Out-of-gamut colours
// give negative components; they are not clipped here.
glm::dvec3 xyz_to_linear_srgb(const glm::dvec3& xyz);

// The piecewise sRGB transfer function, 0..1 to 0..1 (inputs outside are clamped).
double srgb_encode(double linear);
double srgb_decode(double encoded);

// Linear value to 8-bit sRGB code (clamped, rounded to nearest) and back.
std::uint8_t linear_to_srgb8(double linear);
double srgb8_to_linear(std::uint8_t code);

glm::u8vec3 linear_to_srgb8(const glm::dvec3& linear);
glm::dvec3 srgb8_to_linear(const glm::u8vec3& code);

}  // namespace gem
