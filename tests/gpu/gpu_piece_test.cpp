// Stones placed in a piece are traced on the GPU in their own frames: a diamond turned and
// moved off the piece's centre must draw what the CPU reference of the same piece draws (an
// independent renderer, itself checked against the loose stone's reference), and must not
// draw what the same stone drawn loose at the centre would.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/cuts.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/render_target.hpp"
#include "gpu_test_support.hpp"
#include "render/reference_render.hpp"

namespace gem {
namespace {

constexpr int kSize = 96;

Piece placed_diamond() {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.width_mm = 4.0;
    Piece piece;
    piece.name = "placed";
    piece.kinds.push_back(make_cut(p, find_material("diamond").value()).value());
    const double a = 25.0 * 3.14159265358979323846 / 180.0;
    // Turned 25° about x, then moved off the centre.
    const glm::dmat3 turn(1, 0, 0, 0, std::cos(a), std::sin(a), 0, -std::sin(a), std::cos(a));
    piece.stones.push_back({0, {turn, {1.5, -0.7, 0.4}}, "centre"});
    return piece;
}

RenderSettings settings() {
    RenderSettings s;
    s.width = s.height = kSize;
    s.samples_per_pixel = 1;
    s.camera.elevation_deg = 40.0;
    s.camera.azimuth_deg = 10.0;
    s.camera.zoom = 0.9;
    s.trace.max_depth = 8;
    s.shading.lights = {{{20.0, 60.0, 40.0}, false, {2.0, 2.0, 2.0}}};
    return s;
}

Image draw_on_gpu(const Piece* piece, const Stone* loose, double framing_mm) {
    const Environment environment = Environment::studio();
    const RenderSettings s = settings();
    gpu::FrameSetup setup;
    setup.method = gpu::Method::trace;
    setup.piece = piece;
    if (loose != nullptr) {
        setup.stone = *loose;
        setup.material = loose->material;
    }
    setup.shading = s.shading;
    setup.trace = s.trace;
    setup.environment = &environment;
    setup.cube_face = 128;
    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    EXPECT_TRUE(renderer.ok()) << renderer.error();
    if (!renderer) return {};
    auto target = gpu::RenderTarget::make(kSize, kSize);
    EXPECT_TRUE(target.ok()) << target.error();
    target.value().bind();
    auto camera = Camera::make(s.camera, framing_mm, kSize, kSize);
    EXPECT_TRUE(camera.ok()) << camera.error();
    auto stats = renderer.value().render(camera.value(), gpu::FrameWait::frame);
    EXPECT_TRUE(stats.ok()) << stats.error();
    return target.value().read();
}

TEST(GpuPiece, AStoneTurnedAndMovedInAPieceIsTracedInItsOwnFrame) {
    ASSERT_TRUE(gpu_test::context().ok());
    const Piece piece = placed_diamond();
    const double framing = piece.radius_mm();
    const Image gpu = draw_on_gpu(&piece, nullptr, framing);
    auto reference = render_piece_reference(piece, Environment::studio(), settings());
    ASSERT_TRUE(reference) << reference.error();
    const double placed = gpu_test::psnr_srgb8(gpu, reference.value(), true);
    // The same stone drawn loose at the centre: what ignoring the placement would draw.
    const Image loose = draw_on_gpu(nullptr, &piece.kinds[0], framing);
    const double ignored = gpu_test::psnr_srgb8(loose, reference.value(), true);
    if (placed < 38.0) {
        gpu_test::write_artifact(gpu, "piece_placed_gpu");
        gpu_test::write_artifact(reference.value(), "piece_placed_reference");
    }
    std::printf("placed stone: GPU trace against the CPU reference %.1f dB; drawn loose %.1f dB\n",
                placed, ignored);
    EXPECT_GT(placed, 38.0);
    EXPECT_LT(ignored, 20.0);
}

}  // namespace
}  // namespace gem
