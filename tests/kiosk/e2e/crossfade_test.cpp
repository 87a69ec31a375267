// The preset cross-fade: the held picture lies over the new one with an opacity falling
// linearly in time, blended in linear light. Checked on solid colours whose mix is worked out
// by hand.
#include <GLES3/gl3.h>
#include <gtest/gtest.h>

#include <memory>

#include "e2e_fixture.hpp"
#include "passes/crossfade.hpp"

namespace gem::kiosk {
namespace {

void fill(const gpu::RenderTarget& target, glm::vec3 linear) {
    target.bind();
    glClearColor(linear.x, linear.y, linear.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

TEST(CrossFade, HeldPictureFadesLinearlyInLinearLight) {
    auto context = kiosk_e2e::make_context_current();
    ASSERT_TRUE(context.ok()) << context.error();
    auto picture = gpu::RenderTarget::make(8, 4);
    auto fade = CrossFade::make(8, 4);
    ASSERT_TRUE(picture.ok() && fade.ok());

    // Red is held at t = 10 s for 0.4 s; the new frames are blue.
    fill(picture.value(), {1.0f, 0.0f, 0.0f});
    fade.value().hold(picture.value(), 10.0, 0.4);
    EXPECT_DOUBLE_EQ(fade.value().opacity(10.0), 1.0);
    EXPECT_NEAR(fade.value().opacity(10.1), 0.75, 1e-12);
    EXPECT_DOUBLE_EQ(fade.value().opacity(10.4), 0.0);
    EXPECT_FALSE(fade.value().active(10.4));

    // At 10.3 s the held red has opacity 0.25: 0.25 red + 0.75 blue in linear light.
    fill(picture.value(), {0.0f, 0.0f, 1.0f});
    ASSERT_TRUE(fade.value().draw(picture.value(), 10.3).ok());
    const Image mixed = picture.value().read();
    for (const glm::vec4& p : mixed.pixels) {
        // Stored as 8-bit sRGB: one code step is at most ~1/255 in linear light at these levels.
        EXPECT_NEAR(p.x, 0.25f, 0.01f);
        EXPECT_NEAR(p.y, 0.0f, 0.003f);
        EXPECT_NEAR(p.z, 0.75f, 0.01f);
    }

    // After the end the frame is left alone.
    fill(picture.value(), {0.0f, 1.0f, 0.0f});
    ASSERT_TRUE(fade.value().draw(picture.value(), 11.0).ok());
    EXPECT_NEAR(picture.value().read().pixels[0].y, 1.0f, 1e-3f);
    EXPECT_NEAR(picture.value().read().pixels[0].x, 0.0f, 1e-3f);
}

}  // namespace
}  // namespace gem::kiosk
