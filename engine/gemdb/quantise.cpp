#include "gemdb/quantise.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

namespace gem {

namespace {

// Sign that treats zero as positive, so the fold of the lower hemisphere is well defined on
// the coordinate planes.
double sign_not_zero(double x) {
    return x < 0.0 ? -1.0 : 1.0;
}

std::uint16_t quantise_unit_interval(double t) {  // t in [-1, 1]
    const double scaled = std::round((std::clamp(t, -1.0, 1.0) + 1.0) * 0.5 * 65535.0);
    return static_cast<std::uint16_t>(scaled);
}

double dequantise_unit_interval(std::uint16_t q) {
    return q / 65535.0 * 2.0 - 1.0;
}

}  // namespace

OctCode encode_octahedral(const glm::dvec3& direction) {
    const double l1 = std::abs(direction.x) + std::abs(direction.y) + std::abs(direction.z);
    assert(l1 > 0.0);
    glm::dvec3 p = direction / l1;
    double u = p.x;
    double v = p.y;
    if (p.z < 0.0) {
        u = (1.0 - std::abs(p.y)) * sign_not_zero(p.x);
        v = (1.0 - std::abs(p.x)) * sign_not_zero(p.y);
    }
    return {quantise_unit_interval(u), quantise_unit_interval(v)};
}

glm::dvec3 decode_octahedral(OctCode code) {
    const double u = dequantise_unit_interval(code.u);
    const double v = dequantise_unit_interval(code.v);
    glm::dvec3 p{u, v, 1.0 - std::abs(u) - std::abs(v)};
    if (p.z < 0.0) {
        p.x = (1.0 - std::abs(v)) * sign_not_zero(u);
        p.y = (1.0 - std::abs(u)) * sign_not_zero(v);
    }
    return glm::normalize(p);
}

std::uint16_t float_to_half(float value) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    const std::uint32_t sign = (bits >> 16) & 0x8000u;
    const std::uint32_t exponent = (bits >> 23) & 0xFFu;
    const std::uint32_t mantissa = bits & 0x7FFFFFu;
    if (exponent == 0xFFu) {  // infinity, or NaN with a quiet bit so it stays NaN
        return static_cast<std::uint16_t>(sign | 0x7C00u | (mantissa != 0 ? 0x200u : 0u));
    }
    const int unbiased = static_cast<int>(exponent) - 127;
    if (unbiased > 15) return static_cast<std::uint16_t>(sign | 0x7C00u);
    if (unbiased >= -14) {
        // Normal half: drop 13 mantissa bits, round half to even; a carry into the exponent
        // is the correct next binade (or infinity past 65504).
        std::uint32_t half = (static_cast<std::uint32_t>(unbiased + 15) << 10) | (mantissa >> 13);
        const std::uint32_t rest = mantissa & 0x1FFFu;
        if (rest > 0x1000u || (rest == 0x1000u && (half & 1u) != 0)) ++half;
        return static_cast<std::uint16_t>(sign | half);
    }
    // Subnormal half: the value in units of 2^-24 is (1.m) · 2^(e+24), a right shift of the
    // 24-bit significand by -(e+1) bits.
    const int shift = -(unbiased + 1);
    if (exponent == 0 || shift > 24) return static_cast<std::uint16_t>(sign);
    const std::uint32_t significand = mantissa | 0x800000u;
    std::uint32_t half = significand >> shift;
    const std::uint32_t rest = significand & ((1u << shift) - 1u);
    const std::uint32_t halfway = 1u << (shift - 1);
    if (rest > halfway || (rest == halfway && (half & 1u) != 0)) ++half;
    return static_cast<std::uint16_t>(sign | half);
}

float half_to_float(std::uint16_t half) {
    const std::uint32_t sign = (static_cast<std::uint32_t>(half) & 0x8000u) << 16;
    const std::uint32_t exponent = (half >> 10) & 0x1Fu;
    const std::uint32_t mantissa = half & 0x3FFu;
    if (exponent == 0) {
        const float magnitude = std::ldexp(static_cast<float>(mantissa), -24);
        return sign != 0 ? -magnitude : magnitude;
    }
    if (exponent == 0x1Fu) return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << 13));
    return std::bit_cast<float>(sign | ((exponent + 112u) << 23) | (mantissa << 13));
}

PositionCode encode_position(const glm::dvec3& position, const PositionBox& box) {
    const glm::dvec3 extent = box.max - box.min;
    assert(extent.x > 0.0 && extent.y > 0.0 && extent.z > 0.0);
    const glm::dvec3 t = glm::clamp((position - box.min) / extent, 0.0, 1.0);
    const glm::dvec3 q = glm::round(t * 65535.0);
    return {static_cast<std::uint16_t>(q.x), static_cast<std::uint16_t>(q.y),
            static_cast<std::uint16_t>(q.z)};
}

glm::dvec3 decode_position(PositionCode code, const PositionBox& box) {
    const glm::dvec3 q{code.x, code.y, code.z};
    return box.min + q / 65535.0 * (box.max - box.min);
}

}  // namespace gem
