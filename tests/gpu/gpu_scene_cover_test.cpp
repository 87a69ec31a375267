// The tiles a frame's scene covers (gpu/scene_cover.hpp, FrameRenderer::cover()): every pixel
// the shipped halo draws, at 4× MSAA, lies in one of them, as the piece turns, tilts, grows past
// the picture's edge and shrinks. The picture drawn whole, every pixel compared with the
// background's own code, is the independent check. A perspective camera has no cover.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "gpu/frame_renderer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "gpu_test_support.hpp"
#include "optics/colour.hpp"
#include "piece/piece_file.hpp"

namespace gem {
namespace {

struct View {
    double azimuth_deg, elevation_deg, zoom;
    glm::dvec2 shift;
};

TEST(GpuSceneCover, EveryPixelThePieceDrawsIsInACoveredTile) {
    ASSERT_TRUE(gpu_test::context().ok());
    auto halo = load_piece(std::filesystem::path(GEM_CONFIG_DIR) / "pieces" / "halo.toml");
    ASSERT_TRUE(halo) << halo.error();
    const Environment environment = Environment::uniform(glm::dvec3(0.5));
    gpu::FrameSetup setup = gpu_test::trace_setup(&halo.value(), nullptr, environment);
    setup.shading.lights.push_back({{20.0, 60.0, 40.0}, false, {3.0, 3.0, 3.0}});
    setup.trace.max_depth = 4;
    setup.cube_face = 16;
    setup.background_colour = glm::vec3(0.125f, 0.25f, 0.5f);
    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    ASSERT_TRUE(renderer) << renderer.error();
    const int w = 960, h = 600;
    auto picture = gpu::HdrPicture::make(
        w, h, {.samples = 4, .display = {}, .glare = 0.0, .glare_cut = true, .still_frames = 1});
    auto target = gpu::RenderTarget::make(w, h);
    ASSERT_TRUE(picture && target);
    const View views[] = {{10.0, 40.0, 1.0, {0.0, 0.0}},
                          {100.0, 15.0, 1.0, {0.3, -0.2}},
                          {200.0, 85.0, 1.2, {-0.2, 0.1}},
                          {300.0, -30.0, 0.5, {0.6, 0.5}},
                          {45.0, 25.0, 2.5, {0.7, -0.6}}};
    const double framing = renderer.value().scene_radius_mm();
    for (const View& view : views) {
        CameraSettings settings;
        settings.azimuth_deg = view.azimuth_deg;
        settings.elevation_deg = view.elevation_deg;
        settings.zoom = view.zoom;
        settings.shift = view.shift;
        const Camera camera = Camera::make(settings, framing, w, h).value();
        const gpu::SceneCover* cover = renderer.value().cover(camera);
        ASSERT_NE(cover, nullptr);
        const gpu::TileSet tiles = cover->tiles;
        // The whole picture drawn and finished, not only the cover.
        picture.value().begin_frame(false);
        picture.value().bind();
        ASSERT_TRUE(renderer.value().render(camera, gpu::FrameWait::frame).ok());
        ASSERT_TRUE(picture.value().finish(target.value()).ok());
        const Image image = target.value().read();  // top row first
        ASSERT_FALSE(tiles.has_pixel(0, h - 1)) << "the corner shows the background";
        const auto code = [&](int x, int y_up) {
            return glm::ivec3(linear_to_srgb8(
                glm::dvec3(image.pixels[static_cast<std::size_t>(h - 1 - y_up) * w + x])));
        };
        const glm::ivec3 background = code(0, h - 1);
        long drawn = 0, outside = 0;
        gpu::TileSet drawn_tiles(w, h);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                if (code(x, y) == background) continue;
                ++drawn;
                drawn_tiles.mark({x, y, x + 1, y + 1});
                outside += tiles.has_pixel(x, y) ? 0 : 1;
            }
        }
        EXPECT_GT(drawn, 500) << "azimuth " << view.azimuth_deg;
        EXPECT_EQ(outside, 0) << "azimuth " << view.azimuth_deg
                              << ": pixels drawn outside the cover";
        // The cover is the piece's, not the picture's nor the box's about it: the boxes' corners
        // reach past the mesh, and 2 pixels more, into a few tiles about those drawn (1.2 to
        // 1.4 times as many here).
        EXPECT_LE(tiles.tile_count(), drawn_tiles.tile_count() * 3 / 2 + 4)
            << "azimuth " << view.azimuth_deg;
        std::printf("azimuth %5.0f: %ld tiles covered, %ld drawn into\n", view.azimuth_deg,
                    tiles.tile_count(), drawn_tiles.tile_count());
    }
    // A perspective eye sees the boxes otherwise than their orthographic projection: no cover,
    // the picture finished whole.
    CameraSettings near;
    near.perspective_distance_mm = 3.0 * framing;
    EXPECT_EQ(renderer.value().cover(Camera::make(near, framing, w, h).value()), nullptr);
}

}  // namespace
}  // namespace gem
