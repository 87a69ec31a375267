// A regression guard for the whole reference render: the default scene (a Tolkowsky round
// diamond in the studio) at 96 × 96 compared with a committed golden PNG.
//
// To accept an intended change, rerun with GEM_UPDATE_GOLDEN=1 in the environment: the test
// then rewrites tests/golden/render_default_round_96.png instead of comparing. Look at the new
// image before committing it.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cpu/reference_render.hpp"
#include "cpu/scene_settings.hpp"
#include "picture/image.hpp"
#include "scene/scene.hpp"
#include "scene/scene_build.hpp"

namespace gem {
namespace {

// Tolerance, in 8-bit sRGB codes per channel. Facet edges can move a sub-sample from one
// facet to its neighbour under a different compiler or floating-point contraction, which
// changes a handful of edge pixels by a lot; everything else must agree closely.
constexpr int kChannelTolerance = 3;
constexpr double kAllowedShareAbove = 0.01;  // of all pixels

TEST(RenderGolden, DefaultRoundBrilliantMatchesTheGolden) {
    Scene scene = default_scene();
    scene.width = 96;
    scene.height = 96;
    Result<Stone> stone = build_stone(scene);
    ASSERT_TRUE(stone.ok()) << stone.error();
    Result<Environment> env = build_environment(scene);
    ASSERT_TRUE(env.ok()) << env.error();
    Result<Image> image = render_reference(stone.value(), env.value(), render_settings(scene));
    ASSERT_TRUE(image.ok()) << image.error();

    const std::filesystem::path golden =
        std::filesystem::path(GEM_GOLDEN_DIR) / "render_default_round_96.png";
    const char* update = std::getenv("GEM_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        ASSERT_TRUE(write_png(image.value(), golden).ok());
        std::printf("rewrote %s\n", golden.c_str());
        return;
    }

    Result<Image> expected = read_png(golden);
    ASSERT_TRUE(expected.ok()) << expected.error();
    ASSERT_EQ(expected.value().width, 96);
    ASSERT_EQ(expected.value().height, 96);
    const std::vector<std::uint8_t> got = to_srgb8(image.value(), 3);
    const std::vector<std::uint8_t> want = to_srgb8(expected.value(), 3);
    ASSERT_EQ(got.size(), want.size());

    Image diff(96, 96, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    int above = 0;
    int largest = 0;
    for (std::size_t p = 0; p < diff.pixels.size(); ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(got[3 * p + c]) - int(want[3 * p + c]));
            worst = std::max(worst, d);
            // Amplified ×8 so that small differences show.
            diff.pixels[p][c] = std::min(1.0f, d * 8.0f / 255.0f);
        }
        largest = std::max(largest, worst);
        if (worst > kChannelTolerance) ++above;
    }
    const double share = double(above) / double(diff.pixels.size());
    if (share > kAllowedShareAbove) {
        const std::filesystem::path dir = std::filesystem::path(GEM_ARTIFACT_DIR) / "golden";
        std::filesystem::create_directories(dir);
        (void)write_png(image.value(), dir / "render_default_round_96.actual.png");
        (void)write_png(diff, dir / "render_default_round_96.diff.png");
        ADD_FAILURE() << above << " pixels (" << share * 100.0 << " %) differ by more than "
                      << kChannelTolerance << " codes (largest " << largest
                      << "); the render and a diff are in " << dir;
    }
}

}  // namespace
}  // namespace gem
