// A picture drawn and finished around what the piece covers (gpu/hdr_picture.hpp with a
// SceneCover): the same pixels as the picture drawn whole, frame after frame, as the piece
// moves across it, stands still, shrinks and changes its background; the whole picture drawn
// every frame is the independent check. With the glare cut where the display shows none of it,
// no pixel is more than one code from the whole picture (half a step of what the cut glare
// added, and the rounding).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "geometry/cuts.hpp"
#include "gpu/frame_composer.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu_test_support.hpp"
#include "optics/colour.hpp"
#include "optics/material.hpp"
#include "piece/ring_mesh.hpp"

namespace gem {
namespace {

struct Step {
    const char* what;
    glm::dvec2 shift;
    double zoom;
    bool still;
};

TEST(GpuPictureCover, AroundThePieceEachFrameIsThePictureDrawnWhole) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    static const Environment environment = Environment::uniform(glm::dvec3(0.5));
    const Stone stone =
        make_cut(default_cut_params(CutShape::round_brilliant), find_material("diamond").value())
            .value();
    const MetalMesh ring = make_ring({}, stone).value();
    const auto renderer_on = [&](glm::vec3 background) {
        gpu::FrameSetup setup;
        setup.method = "trace";
        setup.stone = stone;
        setup.material = stone.material;
        setup.shading.lights.push_back({{20.0, 60.0, 40.0}, false, {3.0, 3.0, 3.0}});
        setup.trace.max_depth = 4;
        setup.trace_search = gpu::ExitSearch::constants;  // the same pixels from every draw
        setup.environment = &environment;
        setup.cube_face = 16;
        setup.ring = &ring;
        setup.background_colour = background;
        return gpu::FrameRenderer::make(std::move(setup));
    };
    // Wider than tall, as a shop's screen is; the glare's four levels reach far past the ring.
    const int w = 200, h = 128;
    auto covered_target = gpu::RenderTarget::make(w, h);
    auto whole_target = gpu::RenderTarget::make(w, h);
    ASSERT_TRUE(covered_target.ok() && whole_target.ok());

    const Step steps[] = {
        {"first frame", {-0.5, 0.2}, 0.3, false},    {"moved across", {0.55, -0.3}, 0.3, false},
        {"still", {0.55, -0.3}, 0.3, true},          {"still, jittered", {0.55, -0.3}, 0.3, true},
        {"still, settled", {0.55, -0.3}, 0.3, true}, {"grown, at the edge", {0.9, 0.6}, 0.6, false},
        {"small", {0.0, 0.0}, 0.2, false},           {"still again", {0.0, 0.0}, 0.2, true}};
    long smallest_region = long(w) * h;
    struct Glare {
        double share;
        bool cut;
    };
    int most_apart_cut = 0;
    long rewritten_uncut = 0, rewritten_cut = 0;  // the glare's frames' target regions
    for (const Glare glare : {Glare{0.04, false}, Glare{0.04, true}, Glare{0.0, false}}) {
        const gpu::PictureOptions options{.samples = 4,
                                          .display = {},
                                          .glare = glare.share,
                                          .glare_cut = glare.cut,
                                          .still_frames = 3};
        auto covered = gpu::HdrPicture::make(w, h, options);
        auto whole = gpu::HdrPicture::make(w, h,
                                           {.samples = 4,
                                            .display = {},
                                            .glare = glare.share,
                                            .glare_cut = false,
                                            .still_frames = 3});
        ASSERT_TRUE(covered.ok() && whole.ok());
        // Backgrounds of powers of two: the running mean blends a background pixel as
        // bg · (1 − 1/k) + bg · 1/k, which comes back to bg exactly only for such values; for
        // others it drifts by a rounding step every frame wherever it is drawn (all over the whole
        // picture, only around the piece in the covered one), and the glare's tail shows that as
        // single codes along a contour.
        for (const glm::vec3 background :
             {glm::vec3(0.125f, 0.25f, 0.5f), glm::vec3(0.5f, 0.5f, 0.25f)}) {
            auto renderer = renderer_on(background);
            ASSERT_TRUE(renderer.ok()) << renderer.error();
            for (const Step& step : steps) {
                CameraSettings camera;
                camera.elevation_deg = 40.0;
                camera.azimuth_deg = 10.0;
                camera.zoom = step.zoom;
                camera.shift = step.shift;
                const double radius = renderer.value().scene_radius_mm();
                // The cover's picture through the composer; the whole one bound without it.
                covered.value().begin_frame(step.still);
                auto composed = gpu::compose_frame(
                    {.renderer = &renderer.value(),
                     .view = gpu::FrameView{.camera = camera, .framing_mm = radius},
                     .wait = gpu::FrameWait::frame,
                     .picture = &covered.value()},
                    covered_target.value());
                ASSERT_TRUE(composed.ok() && composed.value().scene().ok());
                whole.value().begin_frame(step.still);
                CameraSettings jittered = camera;
                jittered.shift += whole.value().jitter_ndc();
                const Camera c = Camera::make(jittered, radius, w, h).value();
                whole.value().bind();
                ASSERT_TRUE(renderer.value()
                                .render(c, gpu::FrameWait::frame, whole.value().still_frame())
                                .ok());
                ASSERT_TRUE(whole.value().finish(whole_target.value()).ok());
                if (glare.share > 0.0) {
                    (glare.cut ? rewritten_cut : rewritten_uncut) +=
                        covered.value().target_region().area();
                }
                if (glare.share == 0.0) {
                    smallest_region =
                        std::min(smallest_region, covered.value().target_region().area());
                }

                const Image a = covered_target.value().read();
                const Image b = whole_target.value().read();
                int differing = 0, most_apart = 0;
                for (std::size_t i = 0; i < a.pixels.size(); ++i) {
                    int apart = 0;
                    for (int ch = 0; ch < 3; ++ch) {
                        apart = std::max(apart, std::abs(linear_to_srgb8(a.pixels[i][ch]) -
                                                         linear_to_srgb8(b.pixels[i][ch])));
                    }
                    most_apart = std::max(most_apart, apart);
                    differing += apart > (glare.cut ? 1 : 0);
                }
                if (glare.cut) most_apart_cut = std::max(most_apart_cut, most_apart);
                if (differing > 0) {
                    gpu_test::write_artifact(a, "cover-covered");
                    gpu_test::write_artifact(b, "cover-whole");
                    gpu_test::write_artifact(gpu_test::difference_image(a, b, 16.0f), "cover-diff");
                }
                ASSERT_EQ(differing, 0)
                    << step.what << ", glare " << glare.share << (glare.cut ? ", cut" : "")
                    << ": pixels differ from the picture drawn whole (by up to " << most_apart
                    << " codes)";
            }
        }
    }
    // Not a test of nothing: without glare (whose widest level reaches across a picture this
    // small) the small piece's frames rewrote well under half the target.
    EXPECT_LT(smallest_region, long(w) * h / 2);
    // And the cut glare rewrote less than the glare wherever its filters reach.
    EXPECT_LT(rewritten_cut, rewritten_uncut * 9 / 10);
    std::printf(
        "the cut glare's picture at most %d codes from the whole one, rewriting %.0f %% of "
        "what the uncut one did\n",
        most_apart_cut, 100.0 * static_cast<double>(rewritten_cut) / rewritten_uncut);
    EXPECT_TRUE(gpu::gl_check("cover test").ok());
}

}  // namespace
}  // namespace gem
