// The picture's finishing passes (gpu/hdr_picture.hpp): the GPU tone curve against the CPU's
// (picture/tone_map.cpp), multisampled edges against a 16-sample supersampled render, the glare
// keeping the picture's energy, and the framing shift against a plain translation.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/cuts.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu_test_support.hpp"
#include "optics/colour.hpp"
#include "optics/material.hpp"

namespace gem {
namespace {

// Fills a w × h block at (x, y) of the bound framebuffer (y up) with `colour`.
void fill(int x, int y, int w, int h, glm::vec3 colour) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, w, h);
    glClearColor(colour.x, colour.y, colour.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

TEST(GpuPicture, TheFinishPassToneMapsAsTheCpuDoes) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    const int n = 96;
    for (ToneCurve curve : {ToneCurve::neutral, ToneCurve::clip}) {
        const DisplayTransform display{curve, 0.5};
        auto hdr = gpu::HdrPicture::make(n, 1, {.samples = 1, .display = display, .glare = 0.0});
        ASSERT_TRUE(hdr.ok()) << hdr.error();
        ASSERT_TRUE(hdr.value().high_range()) << hdr.value().describe();
        auto picture = gpu::RenderTarget::make(n, 1);
        ASSERT_TRUE(picture.ok()) << picture.error();
        // From black to 40x the display's white, tinted so the channels differ.
        std::vector<glm::dvec3> in(n);
        hdr.value().bind();
        for (int x = 0; x < n; ++x) {
            const double v = 40.0 * std::pow(x / double(n - 1), 3.0);
            in[x] = glm::dvec3(v, 0.55 * v, 0.2 * v);
            fill(x, 0, 1, 1, glm::vec3(in[x]));
        }
        ASSERT_TRUE(hdr.value().finish(picture.value()).ok());
        const Image out = picture.value().read();
        for (int x = 0; x < n; ++x) {
            const glm::dvec3 expected = to_display(in[x], display);
            for (int c = 0; c < 3; ++c) {
                const int got = linear_to_srgb8(out.at(x, 0)[c]);
                const int want = linear_to_srgb8(expected[c]);
                EXPECT_NEAR(got, want, 1) << to_string(curve) << " input " << in[x][c];
            }
        }
    }
    EXPECT_TRUE(gpu::gl_check("tone test").ok());
}

// The diamond drawn by the phong baseline (opaque, flat-shaded facets over black) into an
// HDR picture of `size` with `samples`, finished without a tone curve.
Image draw_diamond(int size, int samples, glm::dvec2 shift = glm::dvec2(0.0)) {
    static const Environment environment = Environment::uniform(glm::dvec3(0.4));
    gpu::FrameSetup setup;
    setup.method = "phong";
    setup.stone =
        make_cut(default_cut_params(CutShape::round_brilliant), find_material("diamond").value())
            .value();
    setup.material = setup.stone.material;
    setup.material.body_colour = {0.9, 0.6, 0.3};
    setup.shading.alpha = 0.0;  // opaque
    setup.shading.lights.push_back({{20.0, 60.0, 40.0}, false, {0.6, 0.6, 0.6}});
    setup.environment = &environment;
    setup.cube_face = 8;
    setup.background_colour = glm::vec3(0.0f);
    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    EXPECT_TRUE(renderer.ok()) << renderer.error();
    CameraSettings settings;
    settings.azimuth_deg = 20.0;
    settings.elevation_deg = 40.0;
    settings.zoom = 0.9;
    settings.shift = shift;
    auto camera = Camera::make(settings, renderer.value().scene_radius_mm(), size, size).value();
    auto hdr = gpu::HdrPicture::make(
        size, size, {.samples = samples, .display = {ToneCurve::clip, 0.0}, .glare = 0.0});
    EXPECT_TRUE(hdr.ok()) << hdr.error();
    auto picture = gpu::RenderTarget::make(size, size);
    hdr.value().bind();
    EXPECT_TRUE(renderer.value().render(camera, gpu::FrameWait::frame).ok());
    EXPECT_TRUE(hdr.value().finish(picture.value()).ok());
    return picture.value().read();
}

TEST(GpuPicture, MultisampledEdgesComeCloserToASupersampledRender) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    const int n = 64, k = 4;
    const Image one = draw_diamond(n, 1);
    const Image msaa = draw_diamond(n, 4);
    // The reference: k × k ordered samples per pixel, a box filter of a render k times larger.
    const Image big = draw_diamond(n * k, 1);
    Image reference(n, n);
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            glm::vec4 sum(0.0f);
            for (int j = 0; j < k; ++j) {
                for (int i = 0; i < k; ++i) sum += big.at(x * k + i, y * k + j);
            }
            reference.at(x, y) = sum / float(k * k);
        }
    }
    // Edge pixels: where the reference's 16 samples disagree (a silhouette or a facet edge).
    double error_one = 0.0, error_msaa = 0.0;
    int edges = 0;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            glm::vec4 lo(1e9f), hi(-1e9f);
            for (int j = 0; j < k; ++j) {
                for (int i = 0; i < k; ++i) {
                    lo = glm::min(lo, big.at(x * k + i, y * k + j));
                    hi = glm::max(hi, big.at(x * k + i, y * k + j));
                }
            }
            if (hi.x - lo.x < 0.05f) continue;
            ++edges;
            error_one += std::abs(one.at(x, y).x - reference.at(x, y).x);
            error_msaa += std::abs(msaa.at(x, y).x - reference.at(x, y).x);
        }
    }
    ASSERT_GT(edges, 100);
    gpu_test::write_artifact(one, "picture_edges_1x");
    gpu_test::write_artifact(msaa, "picture_edges_4x");
    // Four samples leave less than half the single sample's error on the edges.
    EXPECT_LT(error_msaa, 0.5 * error_one)
        << "mean edge error 1x " << error_one / edges << ", 4x " << error_msaa / edges;
}

TEST(GpuPicture, TheGlareSpreadsLightWithoutAddingOrLosingAny) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    const int n = 128;
    auto hdr = gpu::HdrPicture::make(
        n, n, {.samples = 1, .display = {ToneCurve::clip, 0.0}, .glare = 0.5});
    ASSERT_TRUE(hdr.ok()) << hdr.error();
    auto picture = gpu::RenderTarget::make(n, n);
    ASSERT_TRUE(picture.ok());
    hdr.value().bind();
    fill(0, 0, n, n, glm::vec3(0.0f));
    fill(56, 56, 16, 16, glm::vec3(0.9f));
    ASSERT_TRUE(hdr.value().finish(picture.value()).ok());
    const Image out = picture.value().read();
    double sum = 0.0;
    for (const glm::vec4& p : out.pixels) sum += p.x;
    const double energy = 0.9 * 16 * 16;
    EXPECT_NEAR(sum, energy, 0.04 * energy);
    EXPECT_LT(out.at(64, 64).x, 0.85f);  // light leaves the square
    EXPECT_GT(out.at(64, 30).x, 0.0f);   // and reaches pixels far from it
}

TEST(GpuPicture, AShiftTranslatesThePictureByWholePixels) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    const int n = 64;
    const Image plain = draw_diamond(n, 1);
    // ndc (0.25, -0.5) is 8 pixels right and 16 down.
    const Image shifted = draw_diamond(n, 1, {0.25, -0.5});
    int compared = 0, differing = 0;
    for (int y = 0; y + 16 < n; ++y) {
        for (int x = 0; x + 8 < n; ++x) {
            ++compared;
            const glm::vec4 a = plain.at(x, y), b = shifted.at(x + 8, y + 16);
            if (std::abs(linear_to_srgb8(a.x) - linear_to_srgb8(b.x)) > 2) ++differing;
        }
    }
    EXPECT_LE(differing, compared / 100) << differing << " of " << compared;
}

// A still view of many frames is their mean: 1024 frames, each pixel mostly dim and now and
// then bright (as a diamond's fire is from frame to frame), against the mean taken in double.
// In half floats the running mean drifts once an update is below its rounding step.
TEST(GpuPicture, AStillViewOfManyFramesIsTheirMean) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    const int n = 16;
    const int frames = 1024;
    const DisplayTransform display{ToneCurve::clip, 2.0};
    auto hdr = gpu::HdrPicture::make(
        n, 1, {.samples = 1, .display = display, .glare = 0.0, .still_frames = frames});
    ASSERT_TRUE(hdr.ok()) << hdr.error();
    auto picture = gpu::RenderTarget::make(n, 1);
    ASSERT_TRUE(picture.ok()) << picture.error();
    std::vector<double> sum(n, 0.0);
    std::uint32_t state = 12345;
    const auto next = [&state] {  // a fixed LCG: the same frames every run
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / double(1u << 24);
    };
    for (int f = 0; f < frames; ++f) {
        hdr.value().begin_frame(true);
        hdr.value().bind();
        for (int x = 0; x < n; ++x) {
            const double v = next() < 0.03 ? 3.0 : 0.05 + 0.1 * next() * (x + 1) / n;
            sum[x] += v;
            fill(x, 0, 1, 1, glm::vec3(static_cast<float>(v)));
        }
        ASSERT_TRUE(hdr.value().finish(picture.value()).ok());
    }
    const Image out = picture.value().read();
    for (int x = 0; x < n; ++x) {
        const double mean = sum[x] / frames;
        const int want = linear_to_srgb8(to_display(glm::dvec3(mean), display).x);
        EXPECT_NEAR(linear_to_srgb8(out.at(x, 0).x), want, 1)
            << "pixel " << x << ", mean " << mean << "; " << hdr.value().describe();
    }
    EXPECT_TRUE(gpu::gl_check("mean test").ok());
}

// MSAA draws the moving frames and a still view's first (the moving view's own); the still
// frames after it are point samples, whose mean over the sub-pixel offsets has no bias at the
// facet edges MSAA shades at the pixel's centre (hdr_picture.hpp).
TEST(GpuPicture, AStillViewsFramesAfterItsFirstArePointSamples) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto hdr =
        gpu::HdrPicture::make(8, 8, {.samples = 4, .display = {}, .glare = 0.0, .still_frames = 4});
    ASSERT_TRUE(hdr.ok()) << hdr.error();
    if (hdr.value().samples() <= 1) GTEST_SKIP() << "no MSAA here: " << hdr.value().describe();
    const auto bound_samples = [&] {
        hdr.value().bind();
        GLint samples = -1;
        glGetIntegerv(GL_SAMPLES, &samples);
        return samples;
    };
    hdr.value().begin_frame(false);
    EXPECT_EQ(bound_samples(), hdr.value().samples()) << "a moving frame";
    hdr.value().begin_frame(true);
    EXPECT_EQ(bound_samples(), hdr.value().samples()) << "a still view's first frame";
    for (int f = 1; f < 4; ++f) {
        hdr.value().begin_frame(true);
        EXPECT_EQ(bound_samples(), 0) << "still frame " << f;
    }
    EXPECT_TRUE(gpu::gl_check("point samples test").ok());
}

// A still frame that costs more than a touch may wait is drawn in bands, one a frame: each
// band adds its rows with its frame's weight, and the picture shown changes once the frame is
// whole. Frame k clears the picture to its own grey; the frames report 8 ms per unit of depth,
// so from the third frame on (the second measured) a frame at depth 16 takes 128 ms: 2 bands.
TEST(GpuPicture, AStillFrameInBandsIsShownOnceWholeAndAddsEachRowOnce) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    const int n = 8;
    const DisplayTransform display{ToneCurve::clip, 0.0};
    auto made = gpu::HdrPicture::make(n, n,
                                      {.samples = 1,
                                       .display = display,
                                       .glare = 0.0,
                                       .still_frames = 64,
                                       .still_depth = 16,
                                       .still_frame_ms = 100.0});
    ASSERT_TRUE(made.ok()) << made.error();
    gpu::HdrPicture& hdr = made.value();
    auto target = gpu::RenderTarget::make(n, n);
    ASSERT_TRUE(target.ok()) << target.error();
    const auto grey = [](int frame) { return 0.1 + 0.8 * ((frame * 7) % 11) / 10.0; };
    // Every row of the picture shown is the mean of frames 0 .. frames-1.
    const auto expect_mean_of = [&](int frames, const char* when) {
        double mean = 0.0;
        for (int f = 0; f < frames; ++f) mean += grey(f) / frames;
        const int want = linear_to_srgb8(to_display(glm::dvec3(mean), display).x);
        const Image out = target.value().read();
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                EXPECT_NEAR(linear_to_srgb8(out.at(x, y).x), want, 1) << when << ", row " << y;
            }
        }
    };
    int banded = 0;
    bool partial_checked = false;
    hdr.begin_frame(false, 0.0);
    for (int drawn = 0; drawn < 200; ++drawn) {
        hdr.begin_frame(true, 0.0);
        const int frame = hdr.still_frames_drawn() - 1;
        const int bands = hdr.still_schedule().bands();
        if (frame == 13) break;
        hdr.bind();
        glClearColor(float(grey(frame)), 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        ASSERT_TRUE(hdr.finish(target.value()).ok());
        // Each band reports its share of the frame's cost.
        hdr.frame_drawn(8.0 * hdr.still_frame().depth / bands);
        if (bands > 1) ++banded;
        // The first band of frame 12 leaves the picture shown as it was, 12 frames' mean.
        if (frame == 12 && bands > 1 && hdr.target_region().empty()) {
            expect_mean_of(12, "after the first band of frame 12");
            partial_checked = true;
        }
    }
    EXPECT_GT(banded, 10) << "frames drawn in bands";
    EXPECT_TRUE(partial_checked);
    expect_mean_of(13, "after frame 12's last band");
    EXPECT_TRUE(gpu::gl_check("bands test").ok());
}

TEST(GpuPicture, AStillViewDeepensAsItsFramesAccumulateAndEndsWhenItsTimeIsUp) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto made = gpu::HdrPicture::make(8, 8,
                                      {.samples = 1,
                                       .display = {},
                                       .glare = 0.0,
                                       .still_frames = 1024,
                                       .still_depth = 16,
                                       .still_depth_max = 64,
                                       .still_seconds = 2.0});
    ASSERT_TRUE(made.ok()) << made.error();
    gpu::HdrPicture& hdr = made.value();
    hdr.begin_frame(false, 0.0);
    EXPECT_EQ(hdr.still_frame().depth, 0) << "a moving frame traces the moving depth";
    // 40 frames 0.04 s apart: 1.6 s, within the view's 2 s. The rule's depths (StillSchedule):
    // 16 for the first 16 frames, 32 for the next 16, then 64.
    for (int f = 0; f < 40; ++f) {
        hdr.begin_frame(true, 0.04 * f);
        ASSERT_FALSE(hdr.settled()) << f;
        EXPECT_EQ(hdr.still_frame().depth, f < 16 ? 16 : f < 32 ? 32 : 64) << f;
        EXPECT_EQ(hdr.still_frames_drawn(), f + 1);
    }
    hdr.begin_frame(true, 2.0);
    EXPECT_TRUE(hdr.settled());
    EXPECT_TRUE(hdr.refined());
    EXPECT_EQ(hdr.still_frames_drawn(), 40) << "the frame begun at 2 s is not drawn";
    EXPECT_EQ(hdr.still_frame().depth, 0);
    hdr.begin_frame(false, 2.1);  // a touch
    EXPECT_FALSE(hdr.settled());
    EXPECT_EQ(hdr.still_frames_drawn(), 0);
}

// Without a mean a still view is its one frame: once a frame of the view was drawn whole, the
// kiosk need not draw it again (it did, at the display's rate, for as long as nobody touched
// it); a frame with a stand-in for a view not yet resident is drawn again until one is not.
TEST(GpuPicture, WithoutAMeanAStillViewSettlesOnceItIsDrawnWhole) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    gpu::PictureOptions options;
    options.samples = 1;
    options.glare = 0.0;
    options.still_frames = 1;
    auto made = gpu::HdrPicture::make(8, 8, options);
    ASSERT_TRUE(made.ok()) << made.error();
    gpu::HdrPicture& hdr = made.value();
    EXPECT_FALSE(hdr.averages());
    hdr.begin_frame(false, 0.0);
    EXPECT_FALSE(hdr.settled()) << "a moving view";
    hdr.frame_drawn(5.0, /*stand_in=*/true);
    hdr.begin_frame(true, 0.1);
    EXPECT_FALSE(hdr.settled()) << "its last frame stood in for a view";
    hdr.frame_drawn(5.0, false);
    for (int f = 0; f < 3; ++f) {
        hdr.begin_frame(true, 0.2 + 0.1 * f);
        EXPECT_TRUE(hdr.settled()) << "drawn whole, still: frame " << f;
        EXPECT_TRUE(hdr.refined());
    }
    hdr.begin_frame(false, 0.6);  // a touch
    EXPECT_FALSE(hdr.settled());
    hdr.frame_drawn(5.0, false);
    hdr.begin_frame(true, 0.7);
    EXPECT_TRUE(hdr.settled()) << "the moving view's last frame, drawn whole, is the still view";
}

}  // namespace
}  // namespace gem
