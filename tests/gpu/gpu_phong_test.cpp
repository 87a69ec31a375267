// The phong baseline covers exactly the pixels the exact CPU tracer says hit the stone, blends
// with the stated opacity and leaves no GL error.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "geometry/cuts.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/phong_method.hpp"
#include "gpu/render_target.hpp"
#include "gpu_test_support.hpp"
#include "optics/material.hpp"
#include "trace/tracer.hpp"

namespace gem {
namespace {

struct Drawn {
    Image image;
    Camera camera;
    std::string refused;  // the draw's error; empty when it drew
};

// A light up and to the side, h = 40, opacity 1 − alpha.
ShadingSettings shading_with(double alpha) {
    ShadingSettings shading;
    shading.alpha = alpha;
    shading.h = 40.0;
    shading.lights.push_back({{20.0, 60.0, 40.0}, false, {1.0, 1.0, 1.0}});
    return shading;
}

// Draws `stone` over a cleared transparent black target: alpha > 0 marks the stone. The
// method is built for the exponent `built_for_h` (by default the one drawn with).
Drawn draw_phong(const Stone& stone, const CameraSettings& settings, int size,
                 const ShadingSettings& shading, std::optional<double> built_for_h = {}) {
    auto camera = Camera::make(settings, bounding_radius(stone.vertices), size, size);
    EXPECT_TRUE(camera.ok()) << camera.error();
    auto environment =
        gpu::EnvironmentCube::from_environment(Environment::uniform(glm::dvec3(0.5)), 8);
    EXPECT_TRUE(environment.ok()) << environment.error();
    auto target = gpu::RenderTarget::make(size, size);
    EXPECT_TRUE(target.ok()) << target.error();
    auto method = gpu::PhongMethod::make(stone, built_for_h.value_or(shading.h));
    EXPECT_TRUE(method.ok()) << method.error();
    gpu::StoneFrame frame;
    frame.stone = &stone;
    frame.material = stone.material;
    frame.material.body_colour = {0.9, 0.3, 0.2};
    frame.camera = camera.value();
    frame.shading = shading;
    frame.environment = &environment.value();
    frame.scene_radius_mm = bounding_radius(stone.vertices);
    target.value().bind();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    auto drawn = method.value().draw(frame);
    return {target.value().read(), camera.value(), drawn.ok() ? "" : drawn.error()};
}

TEST(GpuPhong, CoverageMatchesTheTracersHitMask) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    for (CutShape shape : {CutShape::round_brilliant, CutShape::heart}) {
        auto stone = make_cut(default_cut_params(shape), find_material("diamond").value());
        ASSERT_TRUE(stone.ok()) << stone.error();
        CameraSettings settings;
        settings.azimuth_deg = 20.0;
        settings.elevation_deg = 40.0;
        const int n = 64;
        const Drawn drawn = draw_phong(stone.value(), settings, n, shading_with(0.4));
        ASSERT_TRUE(drawn.refused.empty()) << drawn.refused;
        const auto path =
            gpu_test::write_artifact(drawn.image, std::string("phong_") + to_string(shape));
        const Tracer tracer(stone.value());
        RayList list;
        int hits = 0, off_edge = 0, on_edge = 0;
        std::vector<bool> cpu(std::size_t(n) * n);
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                tracer.trace(drawn.camera.ray(x + 0.5, y + 0.5), stone.value().material.index(), {},
                             list);
                cpu[std::size_t(y) * n + x] = list.hit;
                hits += list.hit;
            }
        }
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                const bool gpu = drawn.image.at(x, y).w > 0.0f;
                if (gpu == cpu[std::size_t(y) * n + x]) continue;
                // Forgiven on the hit mask's boundary only: a pixel with a 4-neighbour of the
                // other kind, where pixel-centre sampling and rasterisation may differ.
                bool edge = false;
                for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx >= 0 && ny >= 0 && nx < n && ny < n &&
                        cpu[std::size_t(ny) * n + nx] != cpu[std::size_t(y) * n + x]) {
                        edge = true;
                    }
                }
                edge ? ++on_edge : ++off_edge;
            }
        }
        EXPECT_GT(hits, n * n / 5) << to_string(shape);
        EXPECT_EQ(off_edge, 0) << to_string(shape) << ": see " << path;
        EXPECT_LE(on_edge, hits / 10) << to_string(shape);
    }
    auto clean = gpu::gl_check("phong test");
    EXPECT_TRUE(clean.ok()) << clean.error();
}

TEST(GpuPhong, OpacityIsOneMinusTransparency) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto stone =
        make_cut(default_cut_params(CutShape::round_brilliant), find_material("diamond").value());
    ASSERT_TRUE(stone.ok()) << stone.error();
    CameraSettings top;  // straight down: the centre pixel sees the table over the pavilion
    const double alpha = 0.4;
    const Drawn drawn = draw_phong(stone.value(), top, 32, shading_with(alpha));
    ASSERT_TRUE(drawn.refused.empty()) << drawn.refused;
    // Two layers (a back facet, then the table) over alpha 0, each blended with
    // GL_SRC_ALPHA / GL_ONE_MINUS_SRC_ALPHA on alpha too: a' = o·o + (1 − o)·a, o = 1 − α.
    // The target stores alpha in 8 bits.
    const double o = 1.0 - alpha;
    const double one_layer = o * o;
    EXPECT_NEAR(drawn.image.at(16, 16).w, o * o + (1.0 - o) * one_layer, 1.5 / 255.0);
    EXPECT_EQ(drawn.image.at(0, 0).w, 0.0f);  // a corner the stone does not reach
}

// The specular falloff (r·v)^h, compiled in as repeated squaring for a whole h and taken by
// pow for any other (specular.glsl), against the Phong formula by hand at the table's centre.
TEST(GpuPhong, SpecularFalloffFollowsTheExponentWholeOrNot) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto stone =
        make_cut(default_cut_params(CutShape::round_brilliant), find_material("diamond").value());
    ASSERT_TRUE(stone.ok()) << stone.error();
    CameraSettings top;  // straight down: the centre pixel sees the table, n = v = +y
    // A light from a direction l with l.y = 0.98: n.l = 0.98, and r = reflect(−l, n) has
    // r.v = 2 (n.l)(n.v) − l.v = l.y. Opaque (alpha 0): the front facet alone.
    const double l_y = 0.98;
    for (double h : {40.0, 41.5}) {
        ShadingSettings shading;
        shading.alpha = 0.0;
        shading.h = h;
        shading.lights.push_back({{std::sqrt(1.0 - l_y * l_y), l_y, 0.0}, true, {1.0, 1.0, 1.0}});
        const Drawn drawn = draw_phong(stone.value(), top, 32, shading);
        ASSERT_TRUE(drawn.refused.empty()) << drawn.refused;
        // I_o (k_a E + k_d n.l) + k_s (r.v)^h: phong.frag's k_a 0.3, k_d 0.7, the test's
        // environment 0.5 and I_o (0.9, 0.3, 0.2), k_s 1. Green and blue stay below 1, near
        // 0.6-0.7, where a step of the target's sRGB bytes is 0.007 in linear light: rounding
        // is within 0.004. h = 39 or 42 would be 0.009 and more away.
        const double specular = std::pow(l_y, h);
        const glm::vec4 pixel = drawn.image.at(16, 16);
        EXPECT_NEAR(pixel.y, 0.3 * (0.3 * 0.5 + 0.7 * l_y) + specular, 0.005) << h;
        EXPECT_NEAR(pixel.z, 0.2 * (0.3 * 0.5 + 0.7 * l_y) + specular, 0.005) << h;
    }
}

// Its programs have the exponent compiled in: a draw with another says so and draws nothing.
TEST(GpuPhong, ADrawWithAnotherExponentThanItWasBuiltForIsRefused) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto stone =
        make_cut(default_cut_params(CutShape::round_brilliant), find_material("diamond").value());
    ASSERT_TRUE(stone.ok()) << stone.error();
    ShadingSettings shading = shading_with(0.0);
    shading.h = 60.0;
    const Drawn drawn = draw_phong(stone.value(), CameraSettings{}, 16, shading, 40.0);
    EXPECT_NE(drawn.refused.find("specular exponent of 60,"), std::string::npos) << drawn.refused;
    EXPECT_EQ(drawn.image.at(8, 8).w, 0.0f);  // nothing drawn
}

}  // namespace
}  // namespace gem
