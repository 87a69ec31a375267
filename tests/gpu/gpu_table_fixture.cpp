#include "gpu_table_fixture.hpp"

#include <cmath>
#include <map>
#include <numbers>

#include "geometry/cuts.hpp"
#include "optics/material.hpp"
#include "scene/shading.hpp"
#include "table_build.hpp"

namespace gem::gpu_test {

Result<std::shared_ptr<const Database>> build_database(const Stone& stone, const std::string& name,
                                                       double spacing_deg, double min_elevation_deg,
                                                       bool dispersion) {
    BuildParams params;
    params.levels = {64, 128};
    params.grid.spacing_rad = spacing_deg * std::numbers::pi / 180.0;
    params.grid.min_elevation_rad = min_elevation_deg * std::numbers::pi / 180.0;
    params.max_depth = 8;
    params.weight_threshold = 1e-4;
    params.dispersion = dispersion;
    auto grid = ViewGrid::build(params.grid, stone.symmetry);
    if (!grid) return Error{grid.error()};
    std::filesystem::create_directories(GEM_ARTIFACT_DIR);
    const std::filesystem::path path = std::filesystem::path(GEM_ARTIFACT_DIR) / (name + ".gemdb");
    auto written = tables::trace_and_write(path, stone, params, grid.value(), 2);
    if (!written) return Error{written.error()};
    auto db = Database::open(path);
    if (!db) return Error{db.error()};
    return std::make_shared<const Database>(std::move(db).value());
}

Result<const TableFixture*> round_brilliant_database(double spacing_deg, bool dispersion) {
    static std::map<std::pair<double, bool>, std::unique_ptr<TableFixture>> built;
    auto& slot = built[{spacing_deg, dispersion}];
    if (slot) return slot.get();
    auto stone = make_cut(default_cut_params(CutShape::round_brilliant), *find_material("diamond"));
    if (!stone) return Error{stone.error()};
    auto fixture = std::make_unique<TableFixture>();
    fixture->stone = std::move(stone).value();
    const std::string name =
        "gpu_round_" + std::to_string(int(spacing_deg)) + (dispersion ? "_dn" : "");
    auto db = build_database(fixture->stone, name, spacing_deg, -10.0, dispersion);
    if (!db) return Error{db.error()};
    fixture->database = std::move(db).value();
    fixture->path = fixture->database->path();
    slot = std::move(fixture);
    return slot.get();
}

Result<Camera> table_aligned_camera(const Database& database, const glm::dvec3& view,
                                    double roll_deg, int side, int image) {
    const glm::dvec3 v = glm::normalize(view);
    CameraSettings s;
    s.azimuth_deg = std::atan2(v.x, v.z) * 180.0 / std::numbers::pi;
    s.elevation_deg = std::asin(std::clamp(v.y, -1.0, 1.0)) * 180.0 / std::numbers::pi;
    s.roll_deg = roll_deg;
    // Camera::make sizes pixels as 2R / (zoom · shorter side); the stored view's pixel is
    // field / side.
    const double radius = bounding_radius(database.stone().vertices);
    s.zoom = 2.0 * radius * side / (database.camera().field_mm * image);
    return Camera::make(s, radius, image, image);
}

Image cpu_exact_image(const Stone& stone, const gpu::StoneFrame& frame,
                      const Environment& environment, const TraceSettings& trace) {
    const Camera& camera = frame.camera;
    const Tracer tracer(stone);
    const Shader shader(stone, frame.material, environment, frame.shading);
    Image out(camera.width(), camera.height());
    RayList list;
    const glm::vec3 background(environment.radiance(camera.forward()));
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            tracer.trace(camera.ray(x + 0.5, y + 0.5), frame.material.index(), trace, list);
            out.at(x, y) = list.hit ? glm::vec4(glm::vec3(shader.shade(list)), 1.0f)
                                    : glm::vec4(background, 1.0f);
        }
    }
    return out;
}

}  // namespace gem::gpu_test
