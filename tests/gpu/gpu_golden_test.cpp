// Golden images of the GPU methods through the frame renderer, as gemrender draws them: a
// loose diamond (table, trace, phong), a coloured stone with transparency (trace, thesis
// weights), and a diamond set in a ring (table). 96 × 96, studio environment.
//
// Tolerance, in 8-bit sRGB codes per channel: 3, with at most 1 % of pixels beyond it
// (facet edges can flip between neighbours under another compiler or driver). A failure
// writes the image and |difference| × 4 to the artefact folder. GEM_UPDATE_GOLDEN=1 rewrites
// the goldens instead: look at them before committing.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gpu/frame_renderer.hpp"
#include "gpu/render_target.hpp"
#include "gpu_table_fixture.hpp"
#include "gpu_test_support.hpp"
#include "piece/ring_mesh.hpp"

namespace gem {
namespace {

constexpr int kSize = 96;
constexpr int kChannelTolerance = 3;
constexpr double kAllowedShareAbove = 0.01;

struct GoldenCase {
    const char* name;
    std::string method;
    bool thesis = false;
    bool ring = false;
};

Image render_case(const GoldenCase& c) {
    auto fx = gpu_test::round_brilliant_database();
    EXPECT_TRUE(fx.ok()) << fx.error();
    if (!fx) return {};
    const Environment environment = Environment::studio();
    gpu::FrameSetup setup;
    setup.method = c.method;
    setup.database = fx.value()->database;
    setup.stone = fx.value()->stone;
    setup.material = setup.stone.material;
    setup.shading.lights = {{{20.0, 60.0, 40.0}, false, {2.0, 2.0, 2.0}}};
    setup.trace.max_depth = 8;
    setup.table.wait_for_views = true;
    setup.environment = &environment;
    setup.cube_face = 128;
    // Phong's opacity is 1 − α: at the physical default α = 1 the baseline draws nothing.
    if (c.method == "phong") setup.shading.alpha = 0.4;
    if (c.thesis) {
        setup.shading.model = ShadingModel::thesis;
        setup.shading.alpha = 0.7;
        setup.trace.weights = WeightModel::thesis_factors;
        setup.material.body_colour = {0.1, 0.25, 0.8};  // a sapphire blue
    }
    MetalMesh ring;
    if (c.ring) {
        auto made = make_ring({}, setup.stone);
        EXPECT_TRUE(made.ok()) << made.error();
        ring = std::move(made).value();
        setup.ring = &ring;
    }
    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    EXPECT_TRUE(renderer.ok()) << renderer.error();
    if (!renderer) return {};
    auto target = gpu::RenderTarget::make(kSize, kSize);
    EXPECT_TRUE(target.ok()) << target.error();
    target.value().bind();
    CameraSettings cs;
    cs.elevation_deg = 40.0;
    cs.azimuth_deg = 10.0;
    cs.zoom = c.ring ? 0.6 : 1.0;
    auto camera = Camera::make(cs, renderer.value().stone_radius_mm(), kSize, kSize);
    EXPECT_TRUE(camera.ok()) << camera.error();
    auto stats = renderer.value().render(camera.value(), gpu::FrameWait::frame);
    EXPECT_TRUE(stats.ok()) << stats.error();
    return target.value().read();
}

class GpuGolden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GpuGolden, MatchesTheGolden) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    const GoldenCase& c = GetParam();
    const Image image = render_case(c);
    ASSERT_EQ(image.width, kSize);
    const std::filesystem::path golden =
        std::filesystem::path(GEM_GOLDEN_DIR) / (std::string("gpu_") + c.name + ".png");
    const char* update = std::getenv("GEM_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        ASSERT_TRUE(write_png(image, golden).ok());
        std::printf("rewrote %s\n", golden.c_str());
        return;
    }
    auto expected = read_png(golden);
    ASSERT_TRUE(expected.ok()) << expected.error();
    const std::vector<std::uint8_t> got = to_srgb8(image, 3);
    const std::vector<std::uint8_t> want = to_srgb8(expected.value(), 3);
    ASSERT_EQ(got.size(), want.size());
    int above = 0;
    int largest = 0;
    for (std::size_t p = 0; p < got.size(); p += 3) {
        int worst = 0;
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(got[p + k] - want[p + k]));
        largest = std::max(largest, worst);
        above += worst > kChannelTolerance ? 1 : 0;
    }
    const double share = static_cast<double>(above) / (kSize * kSize);
    if (share > kAllowedShareAbove) {
        const auto a = gpu_test::write_artifact(image, std::string("golden_") + c.name);
        const auto d = gpu_test::write_artifact(gpu_test::difference_image(image, expected.value()),
                                                std::string("golden_") + c.name + "_diff");
        ADD_FAILURE() << c.name << ": " << above << " pixels differ by more than "
                      << kChannelTolerance << " (largest " << largest << "); see " << a << " and "
                      << d;
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuGolden,
                         ::testing::Values(GoldenCase{"table_diamond", "table"},
                                           GoldenCase{"trace_diamond", "trace"},
                                           GoldenCase{"phong_diamond", "phong"},
                                           GoldenCase{"trace_sapphire_thesis", "trace", true},
                                           GoldenCase{"table_ring", "table", false, true}),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace gem
