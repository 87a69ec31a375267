// Pictures of where the shading stage fails on views (docs/failure-modes-views.md): for the
// worst cases the GPU failure tests measure (tests/gpu/failure_*_test.cpp), the render, the
// exact CPU image and the CIEDE2000 heat map of their difference (picture/image_error.hpp),
// side by side. Heat maps run black → red → yellow → white at ΔE00 0 → 20 (red ≈ 7, yellow
// ≈ 13); a ΔE00 above 2 is visible to a shopper.
//
//   failure_gallery [OUTPUT_DIR]      (default docs/images/failures, run from the repo root)
//
// The database is the GPU tests' (tests/gpu/gpu_table_fixture.cpp): the round brilliant in
// diamond, levels 64 and 128, views every 12° above −10° elevation, depth 8.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "../gpu/failure_render.hpp"
#include "geometry/cuts.hpp"
#include "gpu/egl_context.hpp"
#include "optics/material.hpp"
#include "picture/image_error.hpp"
#include "table_build.hpp"

#include "bench_support.hpp"

namespace {

namespace fs = std::filesystem;
constexpr int kImage = 128;
constexpr float kFullScale = 20.0f;

constexpr const char* kProgram = "failure_gallery";
template <class T>
T take(gem::Result<T> r) {
    return gem::bench::must(kProgram, std::move(r));
}

std::shared_ptr<const gem::Database> build_database() {
    auto stone = take(gem::make_cut(gem::default_cut_params(gem::CutShape::round_brilliant),
                                    *gem::find_material("diamond")));
    gem::BuildParams params;
    params.levels = {64, 128};
    params.grid.spacing_rad = 12.0 * std::numbers::pi / 180.0;
    params.grid.min_elevation_rad = -10.0 * std::numbers::pi / 180.0;
    params.max_depth = 8;
    params.weight_threshold = 1e-4;
    auto grid = take(gem::ViewGrid::build(params.grid, stone.symmetry));
    const fs::path path = fs::temp_directory_path() / "failure_gallery.gemdb";
    take(gem::tables::trace_and_write(path, stone, params, grid, 2));
    return std::make_shared<const gem::Database>(take(gem::Database::open(path)));
}

gem::Image heat(const gem::Image& test, const gem::Image& reference) {
    return gem::heat_map(gem::delta_e_map(test, reference), test.width, test.height, kFullScale);
}

void write(const gem::Image& image, const fs::path& path) {
    take(gem::write_png(image, path));
    std::printf("wrote %s (%d×%d, %ju bytes)\n", path.c_str(), image.width, image.height,
                static_cast<std::uintmax_t>(fs::file_size(path)));
}

void print_error(const char* what, const gem::Image& test, const gem::Image& reference) {
    const gem::ImageError e = take(gem::compare_images(test, reference));
    std::printf("  %-34s %5.1f dB  ΔE mean %5.2f  p99 %5.1f  visible %5.1f%%\n", what, e.psnr_db,
                e.delta_e_mean, e.delta_e_p99, 100.0 * e.share_visible);
}

// The camera along `view` whose pixels are the 128 level's (as table_aligned_camera).
gem::Camera aligned(const gem::failure::FailureScene& scene, const glm::dvec3& view) {
    const double radius = gem::bounding_radius(scene.stone().vertices);
    const double zoom = 2.0 * radius * 128.0 / (scene.database().camera().field_mm * kImage);
    return take(scene.camera(view, zoom, kImage));
}

// Case 1: the path from a stored view to its nearest neighbour (as the between-views test).
void between_views(gem::failure::FailureScene& scene, const fs::path& out) {
    using namespace gem::failure;
    const gem::ViewGrid& grid = scene.database().grid();
    std::uint32_t chosen = 0;
    for (std::uint32_t v = 0; v < grid.size(); ++v) {
        if (grid.direction(v).y > 0.3 && grid.direction(v).y < 0.7) chosen = v;
    }
    const std::vector<glm::dvec3> images = stored_images(grid);
    const glm::dvec3 a = grid.direction(chosen);
    const glm::dvec3 b = images[nearest_neighbour(images, a)];
    constexpr int kIntervals = 11;
    auto frame = [&](int k) { return aligned(scene, slerp(a, b, double(k) / kIntervals)); };
    // Just before and after the midpoint, and the stored end b.
    const gem::Camera before = frame(5), after = frame(6), end = frame(11);
    const gem::Image n5 = take(scene.table(before, false)).image;
    const gem::Image n6 = take(scene.table(after, false)).image;
    const gem::Image b5 = take(scene.table(before, true)).image;
    const gem::Image b6 = take(scene.table(after, true)).image;
    const gem::Image x5 = scene.exact(before);
    const gem::Image x6 = scene.exact(after);
    std::printf("between stored views (frame 5 of 11, 5.2° from the nearest):\n");
    print_error("nearest vs exact", n5, x5);
    print_error("blend vs exact", b5, x5);
    write(side_by_side({n5, b5, x5, heat(n5, x5), heat(b5, x5)}), out / "between_views.png");
    std::printf("one 1.04° step across the midpoint (frame 5 → 6):\n");
    print_error("nearest step", n6, n5);
    print_error("blend step", b6, b5);
    print_error("exact step", x6, x5);
    const gem::Image hn = heat(n6, n5), hb = heat(b6, b5), hx = heat(x6, x5);
    write(side_by_side({hn, hb, hx}), out / "midpoint_step.png");
    const gem::Image ne = take(scene.table(end, false)).image;
    const gem::Image be = take(scene.table(end, true)).image;
    const gem::Image xe = scene.exact(end);
    std::printf("at the stored direction b:\n");
    print_error("nearest vs exact", ne, xe);
    print_error("blend vs exact", be, xe);
    write(side_by_side({ne, be, xe, heat(be, xe)}), out / "blend_at_stored_view.png");
}

// Case 2: 60° below the band, and 2° above the girdle plane (inside the band; not 0°, where
// the camera looks along the studio's floor/wall step and only the background differs).
void grazing(gem::failure::FailureScene& scene, const fs::path& out) {
    for (const double elevation : {2.0, -60.0}) {
        const double e = elevation * std::numbers::pi / 180.0;
        const double az = 17.0 * std::numbers::pi / 180.0;
        const gem::Camera camera =
            aligned(scene, {std::cos(e) * std::sin(az), std::sin(e), std::cos(e) * std::cos(az)});
        const auto table = take(scene.table(camera, false));
        const gem::Image exact = scene.exact(camera);
        std::printf("elevation %.0f° (table view %.1f° away):\n", elevation,
                    table.stats.angle_rad * 180.0 / std::numbers::pi);
        print_error("nearest vs exact", table.image, exact);
        write(gem::failure::side_by_side({table.image, exact, heat(table.image, exact)}),
              out / (elevation < 0.0 ? "below_band.png" : "girdle_plane.png"));
    }
}

// Case 4: face-up magnified 8× beyond the 128 level.
void magnified(gem::failure::FailureScene& scene, const fs::path& out) {
    const gem::Camera camera = take(scene.camera({0.0, 1.0, 0.0}, 8.0, kImage));
    const auto table = take(scene.table(camera, false));
    const gem::Image exact = scene.exact(camera);
    std::printf("face-up, zoom 8 (level %u upsampled):\n", table.stats.level);
    print_error("nearest vs exact", table.image, exact);
    write(gem::failure::side_by_side({table.image, exact, heat(table.image, exact)}),
          out / "magnified_x8.png");
}

}  // namespace

int main(int argc, char** argv) {
    const fs::path out = argc > 1 ? fs::path(argv[1]) : fs::path("docs/images/failures");
    fs::create_directories(out);
    auto context = take(gem::gpu::EglContext::headless());
    std::printf("GL: %s\n", context.description().c_str());
    auto scene = take(gem::failure::FailureScene::make(build_database()));
    between_views(scene, out);
    grazing(scene, out);
    magnified(scene, out);
    return 0;
}
