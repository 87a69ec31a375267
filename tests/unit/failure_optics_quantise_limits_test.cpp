// The table format at the edges of its ranges: halves at the subnormal end and next to 1,
// the double rounding of the double → float → half path, path lengths of the longest
// total-internal-reflection paths, exit positions on and just outside the bounding box,
// directions on the octahedral fold seams; then the shaded colour of a real moissanite view
// before and after the payload codec (encode_payload / decode_payload), as ΔE00.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "failure_optics_support.hpp"
#include "gemdb/payload.hpp"
#include "gemdb/quantise.hpp"
#include "picture/image_error.hpp"
#include "scene/environment.hpp"
#include "scene/shading.hpp"

namespace gem {
namespace {

// The correctly rounded binary16 value of x ≥ 0 (round half to even, no overflow), written
// from the format's definition (IEEE 754-2008 §3.6: 10 fraction bits, emin = −14): the
// spacing is 2^(e − 10) in binade e and 2^-24 below 2^-14.
double reference_half(double x) {
    const double q =
        x < std::ldexp(1.0, -14) ? std::ldexp(1.0, -24) : std::ldexp(1.0, std::ilogb(x) - 10);
    return std::nearbyint(x / q) * q;  // x / q is exact: q is a power of two
}

TEST(FailureOpticsQuantiseLimits, HalvesFromSubnormalToOne) {
    int mismatched = 0, values = 0;
    for (double x = 1e-9; x <= 1.0; x *= 1.0007) {
        const double decoded = half_to_float(double_to_half(x));
        EXPECT_LE(std::abs(decoded - x), failure_test::half_bound(x)) << x;
        mismatched += decoded != reference_half(x) ? 1 : 0;
        ++values;
    }
    // Edges: the smallest subnormal, a tie below it (to even: 0), the largest subnormal, the
    // smallest normal, the table's weight threshold, the tie just under 1 (to even: 1).
    EXPECT_EQ(half_to_float(double_to_half(std::ldexp(1.0, -24))), std::ldexp(1.0, -24));
    EXPECT_EQ(half_to_float(double_to_half(std::ldexp(1.0, -25))), 0.0f);
    EXPECT_EQ(half_to_float(double_to_half(std::ldexp(1023.0, -24))), std::ldexp(1023.0, -24));
    EXPECT_EQ(half_to_float(double_to_half(kHalfMinNormal)), kHalfMinNormal);
    EXPECT_NEAR(half_to_float(double_to_half(1e-4)), 1e-4, failure_test::half_bound(1e-4));
    EXPECT_EQ(half_to_float(double_to_half(1.0 - std::ldexp(1.0, -12))), 1.0f);
    EXPECT_EQ(half_to_float(double_to_half(1.0 - std::ldexp(1.0, -11))),
              1.0 - std::ldexp(1.0, -11));
    // Double rounding: 1 + 2^-11 + 2^-40 is just above a half tie, so it rounds up to 1 + 2^-10
    // when rounded once; through float the 2^-40 is lost first, the tie goes to even (1).
    const double x = 1.0 + std::ldexp(1.0, -11) + std::ldexp(1.0, -40);
    EXPECT_EQ(reference_half(x), 1.0 + std::ldexp(1.0, -10));
    EXPECT_EQ(half_to_float(double_to_half(x)), 1.0f);
    EXPECT_LE(std::abs(1.0 - x), failure_test::half_bound(x));  // still within the stated bound
    std::printf("halves: %d of %d log-spaced values in [1e-9, 1] differ from single rounding\n",
                mismatched, values);
}

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

TEST(FailureOpticsQuantiseLimits, DirectionsOnTheOctahedralSeams) {
    EXPECT_NEAR(kOctahedralMaxAngle, 3.0 * std::sqrt(2.0) / 65535.0, 1e-18);
    std::vector<glm::dvec3> seams;
    const double tiny[] = {0.0, -0.0, 1e-300, -1e-300, 1e-9, -1e-9, 3e-5, -3e-5};
    for (double a : tiny) {
        for (double b : tiny) {
            // The poles (+z centre, −z folded to the four corners) and the equator's folds.
            seams.push_back({a, b, 1.0});
            seams.push_back({a, b, -1.0});
            seams.push_back({1.0, a, b});
            seams.push_back({-1.0, a, b});
            seams.push_back({a, 1.0, b});
            seams.push_back({a, -1.0, b});
            seams.push_back({1.0 + a, 1.0, b});
            seams.push_back({-1.0, 1.0 + a, b});
            seams.push_back({0.6 + a, -0.8, b});
            seams.push_back({-0.3, -0.7 + a, b});
        }
    }
    double worst = 0.0;
    for (const glm::dvec3& s : seams) {
        const glm::dvec3 d = glm::normalize(s);
        const double angle = angle_between(decode_octahedral(encode_octahedral(d)), d);
        EXPECT_LE(angle, kOctahedralMaxAngle) << d.x << " " << d.y << " " << d.z;
        worst = std::max(worst, angle);
    }
    std::printf("octahedral seams: worst %.3e rad of the bound %.3e\n", worst, kOctahedralMaxAngle);
}

TEST(FailureOpticsQuantiseLimits, PositionsOnAndJustOutsideTheBox) {
    const PositionBox box{{-3.25, -2.0, -3.25}, {3.25, 0.6513, 3.25}};
    const glm::dvec3 bound = box.max_error();
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                           corner & 4 ? box.max.z : box.min.z};
        for (double out : {0.0, 1e-15, 1e-12}) {
            // Pushed outside along the outward diagonal: clamped back onto the box.
            const glm::dvec3 sign{corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0,
                                  corner & 4 ? 1.0 : -1.0};
            const glm::dvec3 q = p + out * sign;
            const glm::dvec3 error = glm::abs(decode_position(encode_position(q, box), box) - q);
            for (int a = 0; a < 3; ++a) EXPECT_LE(error[a], bound[a] + out + 1e-15);
        }
    }
}

// Shading of the same ray-lists exact and after the payload codec. Uniform grey surround with
// absorption: direction errors cannot matter and the colour bound is derived per ray from the
// half bounds of weight and path: |ΔC| ≤ Σ L·T·(e(w) + w·(exp(σ·e(p)) − 1)).
TEST(FailureOpticsQuantiseLimits, ShadedColourAfterTheCodec) {
    const double n = failure_test::catalogue_index("moissanite");
    Stone stone = failure_test::round_brilliant(n);
    stone.material.absorption_per_mm = {0.80, 0.06, 0.20};  // the catalogue's ruby red
    const Tracer tracer(stone);
    TraceSettings settings;  // the table defaults: depth 12, threshold 1e-4
    const std::uint32_t side = 40;
    const auto lists =
        failure_test::trace_view(tracer, n, settings, failure_test::face_up_view(), side, 7.0);
    PositionBox box{stone.vertices[0], stone.vertices[0]};
    for (const glm::dvec3& v : stone.vertices) {
        box.min = glm::min(box.min, v);
        box.max = glm::max(box.max, v);
    }
    std::vector<std::uint8_t> raw;
    ASSERT_TRUE(encode_payload(lists, nullptr, side, box, 1e-4, raw).ok());
    DecodedView view;
    ASSERT_TRUE(decode_payload(raw, side, false, box, view).ok());

    const glm::dvec3 grey(0.8);
    const Environment uniform = Environment::uniform(grey);
    const Environment studio = Environment::studio();
    ShadingSettings shading;
    shading.lights.push_back({{30.0, 100.0, 40.0}, false, glm::dvec3(3.0)});
    const ShadingSettings no_lights;
    const Shader flat(stone, stone.material, uniform, no_lights);
    const Shader lit(stone, stone.material, studio, shading);
    Image exact_img(side, side), decoded_img(side, side);
    double worst_share = 0.0, longest_path = 0.0;
    for (std::size_t p = 0; p < lists.size(); ++p) {
        if (!lists[p].hit) continue;
        const RayList decoded = ray_list_at(view, p);
        ASSERT_EQ(decoded.exits.size(), lists[p].exits.size());
        glm::dvec3 bound(1e-7);
        auto add = [&](const TracedRay& e) {
            const glm::dvec3 t = glm::exp(-stone.material.absorption_per_mm * e.path_mm);
            const double ep = failure_test::half_bound(e.path_mm);
            bound += grey * t *
                     (failure_test::half_bound(e.weight) +
                      e.weight * (glm::exp(stone.material.absorption_per_mm * ep) - 1.0));
            longest_path = std::max(longest_path, e.path_mm);
        };
        add(lists[p].reflected);
        for (const TracedRay& e : lists[p].exits) add(e);
        const glm::dvec3 diff = glm::abs(flat.shade(decoded) - flat.shade(lists[p]));
        for (int c = 0; c < 3; ++c) {
            EXPECT_LE(diff[c], bound[c]) << "pixel " << p;
            worst_share = std::max(worst_share, diff[c] / bound[c]);
        }
        const auto x = static_cast<int>(p % side), y = static_cast<int>(p / side);
        exact_img.at(x, y) = glm::vec4(glm::vec3(lit.shade(lists[p])), 1.0f);
        decoded_img.at(x, y) = glm::vec4(glm::vec3(lit.shade(decoded)), 1.0f);
    }
    ErrorOptions stone_only;
    stone_only.only_stone = true;
    auto error = compare_images(decoded_img, exact_img, stone_only);
    ASSERT_TRUE(error.ok()) << error.error();
    const ImageError& e = error.value();
    std::printf(
        "codec, uniform surround: worst |dC| %.0f %% of the derived bound; longest "
        "path %.1f mm\ncodec, studio + light: PSNR %.1f dB, dE00 mean %.4f p99 %.4f "
        "max %.4f, %.2f %% visible\n",
        100.0 * worst_share, longest_path, e.psnr_db, e.delta_e_mean, e.delta_e_p99, e.delta_e_max,
        100.0 * e.share_visible);
    // Direction (6.5e-5 rad) and position (5e-5 mm) errors move a ray's environment lookup by
    // far less than a softbox edge's blur and its specular lobe (D·L)^60 by < 60·6.5e-5 of its
    // peak, so no pixel should change visibly.
    EXPECT_LT(e.delta_e_max, kVisibleDeltaE);
    EXPECT_EQ(e.share_visible, 0.0);
}

}  // namespace
}  // namespace gem
