// The one frame composer (gpu/frame_composer.hpp): what the picture shows where no scene is
// drawn, a view whose camera cannot be made, and a frame straight into a target against the
// renderer's own frame. (The composed frame's jitter and cover are checked against a picture
// bound and jittered by hand in gpu_picture_cover_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <optional>

#include "geometry/cuts.hpp"
#include "gpu/frame_composer.hpp"
#include "gpu/render_target.hpp"
#include "gpu_test_support.hpp"
#include "optics/colour.hpp"
#include "optics/material.hpp"
#include "picture/tone_map.hpp"

namespace gem {
namespace {

constexpr int kSide = 96;

Result<gpu::FrameRenderer> loose_diamond(const Stone& stone, const Environment& studio) {
    gpu::FrameSetup setup = gpu_test::trace_setup(nullptr, &stone, studio);
    setup.trace.max_depth = 4;
    setup.cube_face = 64;
    return gpu::FrameRenderer::make(std::move(setup));
}

Stone diamond() {
    return make_cut(default_cut_params(CutShape::round_brilliant), find_material("diamond").value())
        .value();
}

// Pixels whose 8-bit sRGB code is more than one from `expected`'s (display-linear).
int pixels_off(const Image& image, const glm::dvec3& expected) {
    const glm::ivec3 want(linear_to_srgb8(expected));
    int off = 0;
    for (const glm::vec4& p : image.pixels) {
        const glm::ivec3 got(linear_to_srgb8(glm::dvec3(p)));
        const glm::ivec3 d = glm::abs(got - want);
        off += std::max({d.x, d.y, d.z}) > 1 ? 1 : 0;
    }
    return off;
}

gpu::FrameView front_view(const gpu::FrameRenderer& renderer) {
    gpu::FrameView view;
    view.camera.elevation_deg = 40.0;
    view.framing_mm = renderer.stone_radius_mm();
    return view;
}

// A loose diamond in the studio, drawn on the tests' context.
class GpuFrameComposer : public ::testing::Test {
  protected:
    void SetUp() override {
        auto ctx = gpu_test::context();
        ASSERT_TRUE(ctx.ok()) << ctx.error();
        auto made = loose_diamond(stone_, studio_);
        ASSERT_TRUE(made.ok()) << made.error();
        renderer_.emplace(std::move(made).value());
    }
    const Stone stone_ = diamond();
    const Environment studio_ = Environment::studio();
    std::optional<gpu::FrameRenderer> renderer_;
};

TEST_F(GpuFrameComposer, WhereNoSceneIsDrawnThePictureShowsTheSurround) {
    const DisplayTransform display{ToneCurve::neutral, 0.0};
    auto picture = gpu::HdrPicture::make(kSide, kSide, {.samples = 4, .display = display});
    ASSERT_TRUE(picture.ok()) << picture.error();
    auto target = gpu::RenderTarget::make(kSide, kSide);
    ASSERT_TRUE(target.ok()) << target.error();
    // The surround through the CPU's tone curve (picture/tone_map.cpp), the glare of a flat
    // picture adding its own mean.
    const glm::dvec3 surround = to_display(glm::dvec3(gpu::kSurround), display);

    // A stone first, so that a picture left as it was would not pass.
    picture.value().begin_frame(false);
    auto drawn = gpu::compose_frame({.renderer = &*renderer_,
                                     .view = front_view(*renderer_),
                                     .wait = gpu::FrameWait::frame,
                                     .picture = &picture.value()},
                                    target.value());
    ASSERT_TRUE(drawn.ok()) << drawn.error();
    ASSERT_TRUE(drawn.value().scene().ok()) << drawn.value().scene_error;
    EXPECT_GT(pixels_off(target.value().read(), surround), kSide * kSide / 10);

    // No view: the surround alone, no error.
    picture.value().begin_frame(false);
    auto alone =
        gpu::compose_frame({.renderer = &*renderer_, .picture = &picture.value()}, target.value());
    ASSERT_TRUE(alone.ok()) << alone.error();
    EXPECT_FALSE(alone.value().stats);
    EXPECT_EQ(pixels_off(target.value().read(), surround), 0);

    // A view whose camera cannot be made (zoom 0): said in the frame, the surround shown.
    gpu::FrameView broken = front_view(*renderer_);
    broken.camera.zoom = 0.0;
    picture.value().begin_frame(false);
    auto refused = gpu::compose_frame(
        {.renderer = &*renderer_, .view = broken, .picture = &picture.value()}, target.value());
    ASSERT_TRUE(refused.ok()) << refused.error();
    EXPECT_FALSE(refused.value().scene().ok());
    EXPECT_NE(refused.value().scene_error.find("camera"), std::string::npos)
        << refused.value().scene_error;
    EXPECT_EQ(pixels_off(target.value().read(), surround), 0);
}

TEST_F(GpuFrameComposer, AFrameStraightIntoATargetIsTheRenderersOwn) {
    const gpu::FrameView view = front_view(*renderer_);
    auto camera = Camera::make(view.camera, view.framing_mm, kSide, kSide);
    ASSERT_TRUE(camera.ok()) << camera.error();

    auto own = gpu::RenderTarget::make(kSide, kSide);
    ASSERT_TRUE(own.ok()) << own.error();
    own.value().bind();
    ASSERT_TRUE(renderer_->render(camera.value(), gpu::FrameWait::frame).ok());
    auto composed_target = gpu::RenderTarget::make(kSide, kSide);
    ASSERT_TRUE(composed_target.ok()) << composed_target.error();
    auto composed =
        gpu::compose_frame({.renderer = &*renderer_, .view = view, .wait = gpu::FrameWait::passes},
                           composed_target.value());
    ASSERT_TRUE(composed.ok()) << composed.error();
    ASSERT_TRUE(composed.value().scene().ok()) << composed.value().scene_error;
    // Timed pass by pass, as asked; no picture, so no finishing pass.
    EXPECT_GT(composed.value().stats->stone_ms, 0.0);
    EXPECT_EQ(composed.value().finish.tone_ms, 0.0);
    EXPECT_EQ(gpu_test::psnr_srgb8(own.value().read(), composed_target.value().read()),
              std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace gem
