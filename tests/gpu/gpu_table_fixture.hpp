#pragma once
// A small ray-table database built once per test program (as `gemtables build` builds one),
// the scene pieces a GPU frame needs, and the CPU image every GPU method is checked against:
// each pixel centre's ray traced exactly (Camera::ray → Tracer → Shader) and composited over
// the environment, computed without any table or GPU code.

#include <filesystem>
#include <memory>
#include <string>

#include "gemdb/reader.hpp"
#include "geometry/stone.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/frame_uniforms.hpp"
#include "picture/image.hpp"
#include "scene/environment.hpp"
#include "trace/tracer.hpp"
#include "util/result.hpp"

namespace gem::gpu_test {

struct TableFixture {
    Stone stone;
    std::filesystem::path path;
    std::shared_ptr<const Database> database;
};

// A round brilliant diamond, levels {64, 128}, views every `spacing_deg` above −10°
// elevation, depth 8, built into the artefact folder (once per name per program).
Result<const TableFixture*> round_brilliant_database(double spacing_deg = 12.0,
                                                     bool dispersion = false);

// Tables of `stone` (levels {64, 128}, depth 8, views every `spacing_deg` at or above
// `min_elevation_deg`), built into the artefact folder as `name`.gemdb and opened.
Result<std::shared_ptr<const Database>> build_database(const Stone& stone, const std::string& name,
                                                       double spacing_deg, double min_elevation_deg,
                                                       bool dispersion = false);

// The camera that looks along `view` (from the stone toward the eye) with `roll_deg`, its
// pixels the same size as the stored views' at level side `side`, `image` pixels square.
Result<Camera> table_aligned_camera(const Database& database, const glm::dvec3& view,
                                    double roll_deg, int side, int image);

// The exact CPU image of `frame` (1 sample at each pixel centre), background = environment.
Image cpu_exact_image(const Stone& stone, const gpu::StoneFrame& frame,
                      const Environment& environment, const TraceSettings& trace);

}  // namespace gem::gpu_test
