#pragma once
// Quantisation of ray-list fields for the .gemdb format (docs/gemdb-format.md, "Quantisation"):
// unit directions as 2×16-bit octahedral codes, weights / path lengths / derivatives as IEEE
// binary16 halves, exit positions as 16-bit fixed point inside the stone's bounding box.
// Every encoder is exact-rounding so the error bounds below are worst cases, not averages.

#include <cstdint>

#include <glm/glm.hpp>

namespace gem {

// Octahedral encoding (Cigolle, Donow, Evangelakos, Mara, McGuire, Meyer, "A Survey of
// Efficient Representations for Independent Unit Vectors", JCGT 3(2), 2014, §3.3): the
// sphere is projected onto the octahedron |x|+|y|+|z| = 1, the lower half folded over the
// upper, and the square [-1,1]² quantised with 16 bits per component.
struct OctCode {
    std::uint16_t u = 0;
    std::uint16_t v = 0;
};

OctCode encode_octahedral(const glm::dvec3& direction);  // any non-zero length
glm::dvec3 decode_octahedral(OctCode code);              // unit length

// Largest angle (radians) between a unit direction and its decoded code. A code step is
// 2/65535 per component and rounding moves each by at most half a step, δ = 1/65535. On the
// octahedron face z = 1-|u|-|v| that displaces the point by |(du, dv, -du-dv)| ≤ √6·δ (the
// fold onto the lower half is an isometry of the parameter square), and projecting onto the
// sphere (p/|p|) stretches tangential lengths by at most 1/|p| ≤ √3, since |p| ≥ 1/√3 on the
// octahedron. Hence θ ≤ √18·δ = 3√2/65535 ≈ 6.47e-5 rad (0.0037°).
inline constexpr double kOctahedralMaxAngle = 4.242640687119285 / 65535.0;

// IEEE 754 binary16, round to nearest even, overflow to infinity, NaN kept.
std::uint16_t float_to_half(float value);
float half_to_float(std::uint16_t half);
inline std::uint16_t double_to_half(double value) {
    return float_to_half(static_cast<float>(value));
}

// Half precision has an 11-bit significand: for normal values (|x| ≥ 2^-14) rounding to
// nearest gives a relative error ≤ 2^-11; below that (subnormals) the absolute error is
// ≤ 2^-25, half the subnormal spacing 2^-24. The double→float step before it adds up to
// 2^-24 of the value (it can also move a value onto a tie, hence the sum, not the max).
inline constexpr double kHalfMaxRelativeError = 1.0 / 2048.0;
inline constexpr double kHalfMinNormal = 1.0 / 16384.0;
inline constexpr double kHalfMaxSubnormalError = 1.0 / 33554432.0;
inline constexpr double kHalfMaxValue = 65504.0;

// 16-bit fixed point inside an axis-aligned box: 65535 steps per axis, values outside the box
// are clamped onto it. Error per axis ≤ extent / 65535 / 2.
struct PositionBox {
    glm::dvec3 min{0.0};
    glm::dvec3 max{1.0};

    glm::dvec3 max_error() const { return (max - min) / 65535.0 / 2.0; }
};

struct PositionCode {
    std::uint16_t x = 0;
    std::uint16_t y = 0;
    std::uint16_t z = 0;
};

PositionCode encode_position(const glm::dvec3& position, const PositionBox& box);
glm::dvec3 decode_position(PositionCode code, const PositionBox& box);

}  // namespace gem
