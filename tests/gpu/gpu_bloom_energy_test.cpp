// The glare's pyramid (gpu/bloom_pass.hpp) from a picture holding one dim texel: whichever
// texel of a 2×2 block it is, the pyramid must carry its light. Its first step down reads the
// picture with bilinear taps that each average a 2×2 block (shaders/bloom_down.frag); a
// point-sampled read would see one texel of each block and lose a light that falls on the
// others. The top level's sum is levels() blurs of the picture, each holding the picture's
// energy, so its texels summed over their area must give levels() times the texel's light.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include <GLES3/gl3.h>

#include "gpu/bloom_pass.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu_test_support.hpp"

namespace gem {
namespace {

constexpr int kSize = 64;

// The light the pyramid's top level holds, summed over the picture's area.
double glare_energy(int x, int y, float value) {
    std::vector<float> picture(static_cast<std::size_t>(kSize) * kSize * 4, 0.0f);
    picture[(static_cast<std::size_t>(y) * kSize + x) * 4 + 0] = value;
    // The picture as HdrPicture keeps it: RGBA16F, point-sampled (its passes fetch texels).
    gpu::Texture scene = gpu::make_texture_2d(GL_RGBA16F, kSize, kSize, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, scene.get());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, picture.data());
    auto glare = gpu::BloomPass::make(kSize, kSize);
    EXPECT_TRUE(glare) << glare.error();
    if (!glare) return 0.0;
    EXPECT_TRUE(glare.value().run(scene.get()));
    glDisable(GL_SCISSOR_TEST);
    const int w = kSize / 2, h = kSize / 2;  // the top level
    const gpu::Framebuffer read = gpu::make_framebuffer_with(glare.value().glare_texture());
    std::vector<float> top(static_cast<std::size_t>(w) * h * 4);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, top.data());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    double sum = 0.0;
    for (std::size_t i = 0; i < top.size(); i += 4) sum += top[i];
    return sum * 4.0 / glare.value().levels();  // a top-level texel covers 2×2 pixels
}

TEST(GpuBloomEnergy, EveryTexelOfABlockReachesTheGlare) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    // Dim, so Karis' weight 1 / (1 + luma) on the first step barely dims it.
    const float value = 0.01f;
    for (const auto& [x, y] : {std::pair{32, 32}, {33, 32}, {32, 33}, {33, 33}, {21, 40}}) {
        const double energy = glare_energy(x, y, value);
        EXPECT_NEAR(energy, value, 0.05 * value) << "a texel at " << x << ", " << y;
    }
}

}  // namespace
}  // namespace gem
