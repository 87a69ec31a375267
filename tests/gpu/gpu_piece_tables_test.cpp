// A piece's stones of one kind drawn from that kind's tables (gpu/piece_tables.hpp), each in
// its own frame: two diamonds turned apart and moved off the centre, drawn from whole-sphere
// tables, must draw what the CPU reference of the same piece draws (an independent renderer,
// which knows no tables) within the error of showing the nearest stored view, and not what the
// stone drawn unturned would. On a plate of metal, a still view's frames follow the stored exits
// into the piece as the trace's are followed. Tables of another stone, or that stop above the
// horizon, are refused by name.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "cpu/reference_render.hpp"
#include "geometry/cuts.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/render_target.hpp"
#include "gpu_table_fixture.hpp"
#include "gpu_test_support.hpp"

namespace gem {
namespace {

Stone diamond(double width_mm) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.width_mm = width_mm;
    return make_cut(p, find_material("diamond").value()).value();
}

constexpr int kSize = 160;
constexpr int kLevelSide = 64;  // the tables' first level: each stone is drawn from it

// The view every picture here is seen from: an orthographic camera at elevation 40°,
// azimuth 10°, its pixels as large as the tables' at side 64 (so every stored pixel falls on a
// screen pixel: the zoom follows the piece's framing radius).
CameraSettings view_of(const Piece& piece, double field_mm) {
    CameraSettings c;
    c.elevation_deg = 40.0;
    c.azimuth_deg = 10.0;
    c.zoom = 2.0 * piece.radius_mm() * kLevelSide / (field_mm * kSize);
    return c;
}

// Two 4 mm diamonds placed so that each sees the camera exactly along one of the tables'
// stored views (one from above, one from below the girdle), the stored image upright on the
// screen, and moved apart by whole pixels: the stored pixels then land on screen pixels, and
// a stone drawn from its tables in its own frame shows what the CPU traced for that view.
Result<Piece> placed_on_stored_views(const Database& tables) {
    Piece piece;
    piece.name = "two placed";
    piece.kinds.push_back(diamond(4.0));
    CameraSettings direction = view_of(piece, 1.0);
    direction.zoom = 1.0;  // only the camera's axes are wanted here
    auto probe = Camera::make(direction, 1.0, kSize, kSize);
    if (!probe) return Error{probe.error()};
    const glm::dvec3 r = probe.value().right(), u = probe.value().up(), f = probe.value().forward();
    const double pixel = tables.camera().field_mm / kLevelSide;
    const ViewGrid& grid = tables.grid();
    // The first stored view in each band of elevation.
    auto stored_between = [&](double y_low, double y_high) -> std::optional<std::uint32_t> {
        for (std::uint32_t v = 0; v < grid.size(); ++v) {
            if (grid.direction(v).y > y_low && grid.direction(v).y < y_high) return v;
        }
        return std::nullopt;
    };
    const std::optional<std::uint32_t> views[2] = {stored_between(0.4, 0.7),
                                                   stored_between(-0.8, -0.5)};
    const glm::dvec3 offsets_px[2] = {{-38.0, 12.0, 1.3}, {36.0, -20.0, -2.1}};
    for (int i = 0; i < 2; ++i) {
        if (!views[i]) return Error{"no stored view in the elevation band"};
        const CameraBasis b = grid.basis(*views[i]);
        // Takes the stored view's basis (right, up, towards the eye) onto the camera's.
        const glm::dmat3 to_camera(r, u, -f), from_stored(b.right, b.up, b.view);
        const glm::dmat3 rotation = to_camera * glm::transpose(from_stored);
        if (glm::determinant(rotation) < 0.0) return Error{"the two bases differ in handedness"};
        const glm::dvec3& o = offsets_px[i];
        const glm::dvec3 position = (o.x * r + o.y * u) * pixel + o.z * f;
        piece.stones.push_back({0, {rotation, position}, i == 0 ? "above" : "below"});
    }
    return piece;
}

RenderSettings settings(const Piece& piece, double field_mm) {
    RenderSettings s;
    s.width = s.height = kSize;
    s.samples_per_pixel = 1;
    s.camera = view_of(piece, field_mm);
    s.trace.max_depth = 8;
    s.shading.lights = {{{20.0, 60.0, 40.0}, false, {2.0, 2.0, 2.0}}};
    return s;
}

// `table_stats`: where the frame's table figures go. `still_frames` > 0: the mean of that many
// frames of a still view.
Result<Image> draw_on_gpu(const Piece& piece, std::shared_ptr<const Database> tables,
                          double field_mm, gpu::TableFrameStats* table_stats = nullptr,
                          int still_frames = 0) {
    const Environment environment = Environment::studio();
    const RenderSettings s = settings(piece, field_mm);
    gpu::FrameSetup setup;
    setup.method = "trace";
    setup.piece = &piece;
    setup.shading = s.shading;
    setup.trace = s.trace;
    setup.environment = &environment;
    setup.cube_face = 128;
    setup.table.wait_for_views = true;
    setup.kind_tables = {std::move(tables)};
    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    if (!renderer) return Error{renderer.error()};
    auto target = gpu::RenderTarget::make(kSize, kSize);
    if (!target) return Error{target.error()};
    target.value().bind();
    auto camera = Camera::make(s.camera, piece.radius_mm(), kSize, kSize);
    if (!camera) return Error{camera.error()};
    renderer.value().prepare(camera.value(), glm::dvec3(0.0), true);
    if (still_frames > 0) {
        return gpu_test::mean_of_still_frames(renderer.value(), camera.value(), still_frames);
    }
    auto stats = renderer.value().render(camera.value(), gpu::FrameWait::frame);
    if (!stats) return Error{stats.error()};
    if (table_stats != nullptr) *table_stats = stats.value().table;
    return target.value().read();
}

// Whole-sphere tables of the 4 mm diamond, every 6°: built once for the program.
std::shared_ptr<const Database> whole_sphere_tables() {
    static auto built = gpu_test::build_database(diamond(4.0), "piece_diamond_4mm", 6.0, -90.0);
    EXPECT_TRUE(built.ok()) << built.error();
    return built ? built.value() : nullptr;
}

TEST(GpuPieceTables, StonesOfAKindDrawnFromItsTablesMatchTheExactPiece) {
    ASSERT_TRUE(gpu_test::context().ok());
    const auto tables = whole_sphere_tables();
    ASSERT_NE(tables, nullptr);
    auto placed = placed_on_stored_views(*tables);
    ASSERT_TRUE(placed) << placed.error();
    const Piece& piece = placed.value();
    const double field = tables->camera().field_mm;
    auto reference = render_piece_reference(piece, Environment::studio(), settings(piece, field));
    ASSERT_TRUE(reference) << reference.error();
    gpu::TableFrameStats table;
    auto from_tables = draw_on_gpu(piece, tables, field, &table);
    ASSERT_TRUE(from_tables) << from_tables.error();
    EXPECT_TRUE(table.drawn);
    EXPECT_EQ(table.views, 2u);        // one stored view for each stone
    EXPECT_LT(table.angle_rad, 1e-6);  // each seen along its stored view
    auto traced = draw_on_gpu(piece, nullptr, field);
    ASSERT_TRUE(traced) << traced.error();
    // What drawing the stones unturned would show: the same positions, no rotation.
    Piece unturned = piece;
    for (PieceStone& s : unturned.stones) s.placement.rotation = glm::dmat3(1.0);
    auto ignored = draw_on_gpu(unturned, tables, field);
    ASSERT_TRUE(ignored) << ignored.error();
    const double tabled = gpu_test::psnr_srgb8(from_tables.value(), reference.value(), true);
    const double trace = gpu_test::psnr_srgb8(traced.value(), reference.value(), true);
    const double wrong = gpu_test::psnr_srgb8(ignored.value(), reference.value(), true);
    std::printf(
        "two placed diamonds, each seen along a stored view, against the CPU reference: from "
        "their tables %.1f dB, traced %.1f dB, drawn unturned from the tables %.1f dB\n",
        tabled, trace, wrong);
    if (tabled < 35.0) {
        gpu_test::write_artifact(from_tables.value(), "piece_tables_gpu");
        gpu_test::write_artifact(reference.value(), "piece_tables_reference");
    }
    EXPECT_GT(tabled, 35.0);
    EXPECT_LT(wrong, 20.0);
}

// A polished plate of gold 1.5 mm under the lower stone's culet, 16 mm square: what the stones'
// exits see of it, and of each other, the GPU's cube holds only as seen from one point.
Piece on_a_plate(Piece piece) {
    const float y = -3.5f, h = 8.0f;
    piece.metal.positions = {{-h, y, -h}, {h, y, -h}, {h, y, h}, {-h, y, h}};
    piece.metal.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    piece.metal.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from above
    piece.metal.f0 = glm::vec3(1.0f, 0.78f, 0.34f);
    piece.metal.roughness = 0.0f;
    return piece;
}

// The stones drawn from their tables see their piece in a still view: the mean of 17 still
// frames (the moving view's own, then four rounds of tiles) over the stones' pixels comes
// nearer the exact piece than a moving frame by a clear margin (3 dB), and as near as the
// trace's own still frames (within 1.5 dB: the tables store the exits the trace finds, and
// each picks its followed exit by its own chance).
TEST(GpuPieceTables, StonesFromTablesSeeTheirPieceInAStillView) {
    ASSERT_TRUE(gpu_test::context().ok());
    const auto tables = whole_sphere_tables();
    ASSERT_NE(tables, nullptr);
    auto placed = placed_on_stored_views(*tables);
    ASSERT_TRUE(placed) << placed.error();
    const Piece piece = on_a_plate(placed.value());
    const double field = tables->camera().field_mm;
    auto reference = render_piece_reference(piece, Environment::studio(), settings(piece, field));
    ASSERT_TRUE(reference) << reference.error();
    // The stones' pixels: where a reference of the stones alone, framed alike, covers them.
    auto stones =
        render_piece_reference(placed.value(), Environment::studio(), settings(piece, field));
    ASSERT_TRUE(stones) << stones.error();
    auto over_stones = [&](Image image) {
        Image truth = reference.value();
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            image.pixels[i].w = truth.pixels[i].w = stones.value().pixels[i].w;
        }
        return gpu_test::psnr_srgb8(image, truth, true);
    };
    auto moving = draw_on_gpu(piece, tables, field);
    auto still = draw_on_gpu(piece, tables, field, nullptr, 17);
    auto traced_still = draw_on_gpu(piece, nullptr, field, nullptr, 17);
    ASSERT_TRUE(moving && still && traced_still);
    const double m = over_stones(moving.value()), s = over_stones(still.value()),
                 t = over_stones(traced_still.value());
    std::printf(
        "two diamonds on a gold plate, their pixels against the exact piece: from their tables "
        "%.1f dB moving, %.1f dB the mean of 17 still frames; traced, the same %.1f dB\n",
        m, s, t);
    if (s < m + 3.0 || std::abs(s - t) > 1.5) {
        gpu_test::write_artifact(still.value(), "piece_tables_still");
        gpu_test::write_artifact(reference.value(), "piece_tables_plate_reference");
    }
    EXPECT_GT(s, m + 3.0);
    EXPECT_NEAR(s, t, 1.5);
}

TEST(GpuPieceTables, TablesOfAnotherStoneOrAboveTheHorizonOnlyAreRefusedByName) {
    ASSERT_TRUE(gpu_test::context().ok());
    const auto tables = whole_sphere_tables();
    ASSERT_NE(tables, nullptr);
    auto placed = placed_on_stored_views(*tables);
    ASSERT_TRUE(placed) << placed.error();
    const double field = tables->camera().field_mm;
    Piece larger = placed.value();
    larger.kinds[0] = diamond(4.5);
    auto other = draw_on_gpu(larger, tables, field);
    ASSERT_FALSE(other);
    EXPECT_NE(other.error().find("store another stone"), std::string::npos) << other.error();
    EXPECT_NE(other.error().find(tables->path().string()), std::string::npos) << other.error();

    auto above = gpu_test::build_database(diamond(4.0), "piece_diamond_above", 12.0, -10.0);
    ASSERT_TRUE(above) << above.error();
    auto refused = draw_on_gpu(placed.value(), above.value(), field);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find("every direction"), std::string::npos) << refused.error();
}

}  // namespace
}  // namespace gem
