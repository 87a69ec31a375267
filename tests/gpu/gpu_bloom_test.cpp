// The glare pyramid's steps (shaders/bloom_down.frag, shaders/bloom_up.frag) against their
// definitions computed on the CPU in double, with the sampler's clamping at the edges:
// - down: Jimenez's 13 bilinear taps (SIGGRAPH 2014) about the corner between source texels 2J
//   and 2J + 1, grouped in five boxes, each weighted by Karis' 1 / (1 + luma) on the first
//   step;
// - up: at each texel's centre, the 3×3 tent (1 2 1 / 2 4 2 / 1 2 1, over 16) of bilinear
//   samples of the smaller level taken ±1 of its texels apart, plus the level's own
//   downsample; the shader draws the same sum from four bilinear taps.
// At sizes that halve exactly and at those the halving of a 1080-line picture gives (67 from
// 135 and from 33, 135 from 67: not twice).
//
// And the pyramid whole (gpu/bloom_pass.hpp) from a picture holding one dim texel: whichever
// texel of a 2×2 block it is, the pyramid must carry its light. The first step's taps each
// average a 2×2 block; a point-sampled read of the picture (HdrPicture's textures are
// point-sampled) would see one texel of each block and lose a light that falls on the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <GLES3/gl3.h>

#include "gpu/bloom_pass.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/rect_draw.hpp"
#include "gpu/tile_set.hpp"
#include "gpu_test_support.hpp"

namespace gem {
namespace {

struct Level {
    int width, height;
    std::vector<float> rgba;  // row 0 at the bottom, as GL stores it

    float at(int x, int y, int c) const {  // clamped to the edge, as the sampler clamps
        x = std::clamp(x, 0, width - 1);
        y = std::clamp(y, 0, height - 1);
        return rgba[(static_cast<std::size_t>(y) * width + x) * 4 + c];
    }
    // Bilinear at (u, v) in texel units (texel centres at +0.5).
    float bilinear(double u, double v, int c) const {
        const double x = u - 0.5, y = v - 0.5;
        const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
        const double fx = x - x0, fy = y - y0;
        return static_cast<float>((1 - fy) * ((1 - fx) * at(x0, y0, c) + fx * at(x0 + 1, y0, c)) +
                                  fy * ((1 - fx) * at(x0, y0 + 1, c) + fx * at(x0 + 1, y0 + 1, c)));
    }
};

// Values a half float holds exactly, varied enough that a wrong weight shows.
Level pattern(int width, int height, int seed) {
    Level level{width, height, std::vector<float>(static_cast<std::size_t>(width) * height * 4)};
    unsigned state = 2463534242u + static_cast<unsigned>(seed);
    for (float& v : level.rgba) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        v = static_cast<float>(state % 256) / 64.0f;  // 0 .. 4 in steps of 1/64
    }
    return level;
}

// The level as an RGBA16F texture sampled with `filter`.
gpu::Texture upload(const Level& level, GLenum filter = GL_LINEAR) {
    gpu::Texture t = gpu::make_texture_2d(GL_RGBA16F, level.width, level.height, filter);
    glBindTexture(GL_TEXTURE_2D, t.get());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, level.width, level.height, GL_RGBA, GL_FLOAT,
                    level.rgba.data());
    return t;
}

// Draws the program `name` over a target_w × target_h RGBA32F target, once `bind` has bound
// its textures and set its uniforms, and reads the target back (row 0 at the bottom).
template <class Bind>
std::vector<float> draw_step(const char* name, int target_w, int target_h, Bind bind) {
    auto program = gpu::build_program(name);
    EXPECT_TRUE(program) << program.error();
    if (!program) return {};
    const gpu::Texture out = gpu::make_texture_2d(GL_RGBA32F, target_w, target_h, GL_NEAREST);
    const gpu::Framebuffer framebuffer = gpu::make_framebuffer_with(out.get());
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    gpu::RectDraw rects;
    glViewport(0, 0, target_w, target_h);
    glDisable(GL_SCISSOR_TEST);
    {
        const gpu::PipelineScope pass(gpu::Pipeline{&program.value()});
        bind(program.value());
        rects.draw({gpu::PixelRect::whole(target_w, target_h)}, {target_w, target_h});
    }
    std::vector<float> got(static_cast<std::size_t>(target_w) * target_h * 4);
    glReadPixels(0, 0, target_w, target_h, GL_RGBA, GL_FLOAT, got.data());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return got;
}

void expect_step_up_is_the_tent(int source_w, int source_h, int target_w, int target_h) {
    const Level source = pattern(source_w, source_h, 1);
    const Level own = pattern(target_w, target_h, 2);
    const gpu::Texture source_texture = upload(source);
    const gpu::Texture own_texture = upload(own);
    const std::vector<float> got =
        draw_step("bloom_up", target_w, target_h, [&](const gpu::Program& program) {
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, own_texture.get());
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, source_texture.get());
            program.set("u_source", 0);
            program.set("u_own", 1);
            program.set("u_source_texel", glm::vec2(1.0f / source_w, 1.0f / source_h));
            program.set("u_target_texel", glm::vec2(1.0f / target_w, 1.0f / target_h));
        });
    ASSERT_EQ(got.size(), static_cast<std::size_t>(target_w) * target_h * 4);

    const int weights[3] = {1, 2, 1};
    double worst = 0.0;
    for (int y = 0; y < target_h; ++y) {
        for (int x = 0; x < target_w; ++x) {
            // This texel's centre in the smaller level's texel units.
            const double u = (x + 0.5) * source_w / target_w;
            const double v = (y + 0.5) * source_h / target_h;
            for (int c = 0; c < 3; ++c) {
                double tent = 0.0;
                for (int j = -1; j <= 1; ++j) {
                    for (int i = -1; i <= 1; ++i) {
                        tent += weights[i + 1] * weights[j + 1] * source.bilinear(u + i, v + j, c);
                    }
                }
                const double want = own.at(x, y, c) + tent / 16.0;
                const double error =
                    std::abs(got[(static_cast<std::size_t>(y) * target_w + x) * 4 + c] - want);
                worst = std::max(worst, error);
            }
        }
    }
    // Values up to 8; a float bilinear weight rounds at about 1e-6 of them. A tap a texel off,
    // or a weight a sixteenth off, is out by a large share of the 1/64 steps.
    EXPECT_LT(worst, 2e-3) << source_w << "×" << source_h << " up to " << target_w << "×"
                           << target_h;
}

double luma(const double c[3]) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

void expect_step_down_is_jimenez(int source_w, int source_h, bool karis) {
    const int target_w = source_w / 2, target_h = source_h / 2;
    // Dim values, so that Karis' weights differ from box to box without drowning the test.
    Level source = pattern(source_w, source_h, 3);
    for (float& v : source.rgba) v /= 4.0f;
    const gpu::Texture source_texture = upload(source);
    const std::vector<float> got =
        draw_step("bloom_down", target_w, target_h, [&](const gpu::Program& program) {
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D, source_texture.get());
            program.set("u_source", 0);
            program.set("u_karis", karis ? 1 : 0);
            program.set("u_source_texel", glm::vec2(1.0f / source_w, 1.0f / source_h));
        });
    ASSERT_EQ(got.size(), static_cast<std::size_t>(target_w) * target_h * 4);

    double worst = 0.0;
    for (int y = 0; y < target_h; ++y) {
        for (int x = 0; x < target_w; ++x) {
            // A bilinear tap `o` texels from the corner (2x + 1, 2y + 1), in texel units.
            const auto tap = [&](int ox, int oy, double into[3]) {
                for (int c = 0; c < 3; ++c) {
                    into[c] = source.bilinear(2.0 * x + 1 + ox, 2.0 * y + 1 + oy, c);
                }
            };
            // Jimenez's boxes: the inner one of the four taps at ±1, weighted 0.5, and the four
            // corner ones of the taps at 0 and ±2, 0.125 each.
            const int boxes[5][4][2] = {{{-1, 1}, {1, 1}, {-1, -1}, {1, -1}},
                                        {{-2, 2}, {0, 2}, {-2, 0}, {0, 0}},
                                        {{0, 2}, {2, 2}, {0, 0}, {2, 0}},
                                        {{-2, 0}, {0, 0}, {-2, -2}, {0, -2}},
                                        {{0, 0}, {2, 0}, {0, -2}, {2, -2}}};
            const double shares[5] = {0.5, 0.125, 0.125, 0.125, 0.125};
            double sum[3] = {0, 0, 0}, weight = 0.0;
            for (int b = 0; b < 5; ++b) {
                double mean[3] = {0, 0, 0};
                for (const auto& t : boxes[b]) {
                    double v[3];
                    tap(t[0], t[1], v);
                    for (int c = 0; c < 3; ++c) mean[c] += 0.25 * v[c];
                }
                const double w = shares[b] * (karis ? 1.0 / (1.0 + luma(mean)) : 1.0);
                weight += w;
                for (int c = 0; c < 3; ++c) sum[c] += w * mean[c];
            }
            for (int c = 0; c < 3; ++c) {
                const double want = sum[c] / weight;
                const double error =
                    std::abs(got[(static_cast<std::size_t>(y) * target_w + x) * 4 + c] - want);
                worst = std::max(worst, error);
            }
        }
    }
    // Values up to 1 in steps of 1/256; a tap a texel off or a box weighted wrongly is out by
    // a large share of a step.
    EXPECT_LT(worst, 2e-4) << source_w << "×" << source_h << (karis ? " with" : " without")
                           << " Karis' weights";
}

TEST(GpuBloomDown, AStepDownIsJimenezsThirteenTaps) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    for (const bool karis : {true, false}) {
        expect_step_down_is_jimenez(16, 10, karis);
        expect_step_down_is_jimenez(135, 67, karis);
    }
}

TEST(GpuBloomUp, AStepUpIsTheTentOfNineBilinearTaps) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    expect_step_up_is_the_tent(8, 5, 16, 10);
    expect_step_up_is_the_tent(33, 16, 67, 33);
    expect_step_up_is_the_tent(67, 33, 135, 67);
}

// The light the pyramid's top level holds from a picture of one texel of `value` at (x, y),
// summed over the picture's area and divided by the levels: each level is a blur holding the
// picture's energy, and the top level's sum adds them all.
double glare_energy(int x, int y, float value) {
    constexpr int kSize = 64;
    Level picture{kSize, kSize, std::vector<float>(static_cast<std::size_t>(kSize) * kSize * 4)};
    picture.rgba[(static_cast<std::size_t>(y) * kSize + x) * 4] = value;
    // Point-sampled, as HdrPicture keeps its pictures (its passes fetch texels).
    const gpu::Texture scene = upload(picture, GL_NEAREST);
    auto glare = gpu::BloomPass::make(kSize, kSize);
    EXPECT_TRUE(glare) << glare.error();
    if (!glare) return 0.0;
    EXPECT_TRUE(glare.value().run(scene.get()));
    EXPECT_TRUE(glare.value().spread(gpu::TileSet::whole(kSize, kSize)));
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
