// The stones shaded through the visibility pass (FrameSetup::visibility_pass: each stone drawn
// as the rectangle about it, under a stencil test, its entry facets read from the visibility
// target) draw the picture that drawing them facet by facet draws: a piece of 23 stones behind
// and in front of its metal, in a moving frame and in a still one (whose rays follow the
// piece), a loose stone that is not convex, and a piece framed so that its stones run off the
// picture's edge; and the same multisampled. The facet-by-facet pictures are the independent
// side: they are what every other trace test checks against the CPU reference.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "geometry/cuts.hpp"
#include "gpu/frame_composer.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "gpu/visibility_target.hpp"
#include "gpu_test_support.hpp"
#include "optics/colour.hpp"
#include "optics/material.hpp"
#include "piece/piece_file.hpp"

namespace gem {
namespace {

constexpr int kWidth = 160, kHeight = 120;

Result<gpu::FrameRenderer> make_renderer(const Piece* piece, const Stone* loose,
                                         const Environment& studio) {
    gpu::FrameSetup setup = gpu_test::trace_setup(piece, loose, studio);
    setup.shading.lights = {{{20.0, 60.0, 40.0}, false, {2.0, 2.0, 2.0}}};
    setup.trace.max_depth = 6;
    // Both pictures of a pair from one renderer, so the same search and programs draw them.
    setup.trace_search = gpu::ExitSearch::constants;
    setup.cube_face = 64;
    return gpu::FrameRenderer::make(std::move(setup));
}

struct Drawn {
    Image image;
    bool by_visibility = false;
};

// One frame into a single-sample target (`still`: a still view's frame `still`, following
// its rays through the piece).
Drawn draw(gpu::FrameRenderer& renderer, const Camera& camera, bool visibility, int still) {
    auto target = gpu::RenderTarget::make(kWidth, kHeight);
    EXPECT_TRUE(target.ok()) << target.error();
    if (!target) return {};
    target.value().bind();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    renderer.set_visibility_pass(visibility ? gpu::VisibilityPass::always
                                            : gpu::VisibilityPass::off);
    gpu::StillFrame frame;
    frame.index = still;
    auto stats = renderer.render(camera, gpu::FrameWait::frame, frame);
    EXPECT_TRUE(stats.ok()) << stats.error();
    if (!stats) return {};
    return {target.value().read(), stats.value().stones_by_visibility};
}

// The largest 8-bit code apart, over every pixel and channel.
int most_codes_apart(const Image& a, const Image& b) {
    int most = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::ivec3 x(linear_to_srgb8(glm::dvec3(a.pixels[i])));
        const glm::ivec3 y(linear_to_srgb8(glm::dvec3(b.pixels[i])));
        const glm::ivec3 d = glm::abs(x - y);
        most = std::max({most, d.x, d.y, d.z});
    }
    return most;
}

void expect_same_both_ways(gpu::FrameRenderer& renderer, const Camera& camera, int still,
                           const std::string& what) {
    const Drawn facets = draw(renderer, camera, false, still);
    const Drawn visible = draw(renderer, camera, true, still);
    EXPECT_FALSE(facets.by_visibility) << what;
    EXPECT_TRUE(visible.by_visibility) << what;
    const int apart = most_codes_apart(visible.image, facets.image);
    if (apart > 0) {
        gpu_test::write_artifact(visible.image, "visibility-" + what);
        gpu_test::write_artifact(facets.image, "facets-" + what);
    }
    EXPECT_EQ(apart, 0) << what << ": the stones shaded by visibility differ from facet by facet";
}

TEST(GpuVisibility, StonesShadedByVisibilityAreTheStonesShadedFacetByFacet) {
    ASSERT_TRUE(gpu_test::context().ok());
    const Environment studio = Environment::studio();
    auto halo = load_piece(std::filesystem::path(GEM_CONFIG_DIR) / "pieces" / "halo.toml");
    ASSERT_TRUE(halo) << halo.error();
    auto renderer = make_renderer(&halo.value(), nullptr, studio);
    ASSERT_TRUE(renderer) << renderer.error();
    CameraSettings view;
    view.elevation_deg = 40.0;
    view.azimuth_deg = 10.0;
    view.zoom = 1.0;
    const double framing = halo.value().radius_mm();
    auto camera = Camera::make(view, framing, kWidth, kHeight);
    ASSERT_TRUE(camera) << camera.error();
    expect_same_both_ways(renderer.value(), camera.value(), -1, "halo-moving");
    expect_same_both_ways(renderer.value(), camera.value(), 1, "halo-still");
    // Closer, off centre: stones cut by the picture's edges.
    view.zoom = 2.5;
    view.shift = {0.6, -0.4};
    camera = Camera::make(view, framing, kWidth, kHeight);
    ASSERT_TRUE(camera) << camera.error();
    expect_same_both_ways(renderer.value(), camera.value(), -1, "halo-edge");

    const Stone heart =
        make_cut(default_cut_params(CutShape::heart), *find_material("ruby")).value();
    ASSERT_FALSE(heart.convex);
    auto loose = make_renderer(nullptr, &heart, studio);
    ASSERT_TRUE(loose) << loose.error();
    view = {};
    view.elevation_deg = 50.0;
    camera = Camera::make(view, bounding_radius(heart.vertices), kWidth, kHeight);
    ASSERT_TRUE(camera) << camera.error();
    expect_same_both_ways(loose.value(), camera.value(), -1, "heart");
}

// A multisampled frame's stones by visibility: each sample's stone and facet in a multisampled
// integer target (OpenGL ES 3.1), each facet a pixel's samples show traced once and weighed by
// them, written to the samples the stencil keeps. The resolve averages a pixel's samples, so
// the picture is the one drawn facet by facet (each facet's triangle writing its own samples)
// but for the half-float rounding of the weighed mean: a code at most. The metal writes no
// stone at the samples it takes; without that, a pixel whose hidden sample showed another facet
// weighed it (the halo's beads over its stones: 37 pixels up to 160 codes apart). The target is
// cleared about each stone; without that, a sample no stone covers held an earlier frame's
// (the halo after a closer view of it: 5 pixels up to 79 codes apart).
struct Multisampled {
    Image image;
    bool by_visibility = false;
};

Multisampled draw_multisampled(gpu::FrameRenderer& renderer, const CameraSettings& view,
                               double framing, gpu::VisibilityPass visibility) {
    gpu::PictureOptions options;
    options.samples = 4;
    auto picture = gpu::HdrPicture::make(kWidth, kHeight, options);
    EXPECT_TRUE(picture.ok()) << picture.error();
    auto target = gpu::RenderTarget::make(kWidth, kHeight);
    EXPECT_TRUE(target.ok()) << target.error();
    if (!picture || !target) return {};
    renderer.set_visibility_pass(visibility);
    picture.value().begin_frame(false);
    auto composed =
        gpu::compose_frame({.renderer = &renderer,
                            .view = gpu::FrameView{.camera = view, .framing_mm = framing},
                            .wait = gpu::FrameWait::frame,
                            .picture = &picture.value()},
                           target.value());
    EXPECT_TRUE(composed.ok()) << composed.error();
    if (!composed) return {};
    auto stats = composed.value().scene();
    EXPECT_TRUE(stats.ok()) << stats.error();
    if (!stats) return {};
    return {target.value().read(), stats.value().stones_by_visibility};
}

// The pixels more than one code apart, and the largest difference.
struct Apart {
    int pixels = 0;
    int most = 0;
};

Apart codes_apart(const Image& a, const Image& b) {
    Apart apart;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::ivec3 x(linear_to_srgb8(glm::dvec3(a.pixels[i])));
        const glm::ivec3 y(linear_to_srgb8(glm::dvec3(b.pixels[i])));
        const glm::ivec3 d = glm::abs(x - y);
        const int most = std::max({d.x, d.y, d.z});
        apart.most = std::max(apart.most, most);
        if (most > 1) ++apart.pixels;
    }
    return apart;
}

Apart multisampled_both_ways(gpu::FrameRenderer& renderer, const CameraSettings& view,
                             double framing, const std::string& what) {
    const Multisampled facets =
        draw_multisampled(renderer, view, framing, gpu::VisibilityPass::off);
    const Multisampled visible =
        draw_multisampled(renderer, view, framing, gpu::VisibilityPass::always);
    EXPECT_FALSE(facets.by_visibility) << what;
    EXPECT_TRUE(visible.by_visibility) << what;
    const Apart apart = codes_apart(visible.image, facets.image);
    std::printf("%s, 4x MSAA: %d pixels more than a code apart, at most %d codes\n", what.c_str(),
                apart.pixels, apart.most);
    if (apart.most > 1) {
        gpu_test::write_artifact(visible.image, "visibility-msaa-" + what);
        gpu_test::write_artifact(facets.image, "facets-msaa-" + what);
    }
    return apart;
}

TEST(GpuVisibility, AMultisampledFrameIsTheFrameShadedFacetByFacet) {
    ASSERT_TRUE(gpu_test::context().ok());
    const Environment studio = Environment::studio();
    {
        gpu::PictureOptions options;
        options.samples = 4;
        auto picture = gpu::HdrPicture::make(kWidth, kHeight, options);
        ASSERT_TRUE(picture) << picture.error();
        if (picture.value().samples() < 2) GTEST_SKIP() << "this GL multisamples no float target";
    }
    const Stone round =
        make_cut(default_cut_params(CutShape::round_brilliant), *find_material("diamond")).value();
    auto loose = make_renderer(nullptr, &round, studio);
    ASSERT_TRUE(loose) << loose.error();
    if (gpu::max_integer_samples() < 2) {
        GTEST_SKIP() << gpu::multisampled_visibility_note(gpu::max_integer_samples());
    }
    CameraSettings view;
    view.elevation_deg = 40.0;
    // A loose stone: no metal, so the same but for the half floats' rounding.
    EXPECT_LE(
        multisampled_both_ways(loose.value(), view, bounding_radius(round.vertices), "round").most,
        1);
    // As the kiosk chooses (VisibilityPass::where_it_pays): one stone's multisampled frame
    // goes facet by facet, a piece of several stones' by visibility.
    EXPECT_FALSE(draw_multisampled(loose.value(), view, bounding_radius(round.vertices),
                                   gpu::VisibilityPass::where_it_pays)
                     .by_visibility);
    const Stone heart =
        make_cut(default_cut_params(CutShape::heart), *find_material("ruby")).value();
    auto hearts = make_renderer(nullptr, &heart, studio);
    ASSERT_TRUE(hearts) << hearts.error();
    view.elevation_deg = 50.0;
    EXPECT_LE(
        multisampled_both_ways(hearts.value(), view, bounding_radius(heart.vertices), "heart").most,
        1);

    auto halo = load_piece(std::filesystem::path(GEM_CONFIG_DIR) / "pieces" / "halo.toml");
    ASSERT_TRUE(halo) << halo.error();
    auto piece = make_renderer(&halo.value(), nullptr, studio);
    ASSERT_TRUE(piece) << piece.error();
    view.elevation_deg = 40.0;
    view.azimuth_deg = 10.0;
    EXPECT_LE(multisampled_both_ways(piece.value(), view, halo.value().radius_mm(), "halo").most,
              1);
    EXPECT_TRUE(draw_multisampled(piece.value(), view, halo.value().radius_mm(),
                                  gpu::VisibilityPass::where_it_pays)
                    .by_visibility);
    // After a frame by visibility where the centre stone filled the picture: the samples it
    // no longer covers still hold that frame's stones and facets.
    view.zoom = 6.0;
    (void)multisampled_both_ways(piece.value(), view, halo.value().radius_mm(), "halo-close");
    view.zoom = 1.0;
    EXPECT_LE(
        multisampled_both_ways(piece.value(), view, halo.value().radius_mm(), "halo-after").most,
        1);
    // Closer, off centre: stones cut by the picture's edges.
    view.zoom = 2.5;
    view.shift = {0.6, -0.4};
    EXPECT_LE(
        multisampled_both_ways(piece.value(), view, halo.value().radius_mm(), "halo-edge").most, 1);
}

// Where the GL has no multisampled integer texture, the target attaches to a single-sample
// framebuffer only, and says why a multisampled one's stones go facet by facet.
TEST(GpuVisibility, WithoutAMultisampledIntegerTextureOnlyASingleSampleFrameTakesTheTarget) {
    ASSERT_TRUE(gpu_test::context().ok());
    gpu::PictureOptions options;
    options.samples = 4;
    auto picture = gpu::HdrPicture::make(kWidth, kHeight, options);
    ASSERT_TRUE(picture) << picture.error();
    if (picture.value().samples() < 2) GTEST_SKIP() << "this GL multisamples no float target";
    auto single = gpu::RenderTarget::make(kWidth, kHeight);
    ASSERT_TRUE(single) << single.error();
    const glm::ivec2 size(kWidth, kHeight);
    for (const int max : {0, gpu::max_integer_samples()}) {
        gpu::VisibilityTarget target(max);
        EXPECT_EQ(gpu::multisampled_visibility_note(max).empty(), max >= 2) << max;
        picture.value().bind(nullptr);  // the multisampled frame's framebuffer
        const gpu::VisibilityAttachment multisampled =
            target.attach(size, picture.value().samples());
        EXPECT_EQ(multisampled.texture != 0, max >= picture.value().samples()) << max;
        EXPECT_EQ(multisampled.samples, multisampled.texture != 0 ? picture.value().samples() : 0);
        target.detach();
        single.value().bind();
        const gpu::VisibilityAttachment one = target.attach(size, 0);
        EXPECT_NE(one.texture, 0u) << max;
        EXPECT_EQ(one.samples, 0) << max;
        target.detach();
    }
    EXPECT_TRUE(gpu::gl_check("visibility targets").ok());
}

}  // namespace
}  // namespace gem
