// The stones shaded through the visibility pass (FrameSetup::visibility_pass: each stone drawn
// as the rectangle about it, under a stencil test, its entry facets read from the visibility
// target) draw the picture that drawing them facet by facet draws: a piece of 23 stones behind
// and in front of its metal, in a moving frame and in a still one (whose rays follow the
// piece), a loose stone that is not convex, and a piece framed so that its stones run off the
// picture's edge. The facet-by-facet pictures are the independent side: they are what every
// other trace test checks against the CPU reference. A multisampled frame takes the facets.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "geometry/cuts.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/picture_frame.hpp"
#include "gpu/render_target.hpp"
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
    renderer.set_visibility_pass(visibility);
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

// A multisampled picture's frame cannot read a single-sample visibility target: its stones go
// facet by facet, and a still view's frames after the first (single samples) by visibility.
TEST(GpuVisibility, AMultisampledFrameShadesFacetByFacet) {
    ASSERT_TRUE(gpu_test::context().ok());
    const Environment studio = Environment::studio();
    const Stone round =
        make_cut(default_cut_params(CutShape::round_brilliant), *find_material("diamond")).value();
    auto renderer = make_renderer(nullptr, &round, studio);
    ASSERT_TRUE(renderer) << renderer.error();
    gpu::PictureOptions options;
    options.samples = 4;
    options.still_frames = 4;
    auto picture = gpu::HdrPicture::make(kWidth, kHeight, options);
    ASSERT_TRUE(picture) << picture.error();
    if (picture.value().samples() < 2) GTEST_SKIP() << "this GL multisamples no float target";
    auto target = gpu::RenderTarget::make(kWidth, kHeight);
    ASSERT_TRUE(target) << target.error();
    CameraSettings view;
    view.elevation_deg = 40.0;
    const double framing = bounding_radius(round.vertices);
    auto moving = gpu::draw_picture_frame(renderer.value(), picture.value(), view, framing, false,
                                          gpu::FrameWait::frame, target.value());
    ASSERT_TRUE(moving) << moving.error();
    EXPECT_FALSE(moving.value().stones_by_visibility);
    auto first = gpu::draw_picture_frame(renderer.value(), picture.value(), view, framing, true,
                                         gpu::FrameWait::frame, target.value());
    ASSERT_TRUE(first) << first.error();
    EXPECT_FALSE(first.value().stones_by_visibility);  // the moving view's own, multisampled
    auto second = gpu::draw_picture_frame(renderer.value(), picture.value(), view, framing, true,
                                          gpu::FrameWait::frame, target.value());
    ASSERT_TRUE(second) << second.error();
    EXPECT_TRUE(second.value().stones_by_visibility);
}

}  // namespace
}  // namespace gem
