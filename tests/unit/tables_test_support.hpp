#pragma once
// Shared pieces of the tables_* tests: hand-built point groups and stones, random but valid
// ray-lists, and a small database written through a stand-in tracer.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/glm.hpp>

#include "gemdb/database_types.hpp"
#include "gemdb/view_grid.hpp"
#include "gemdb/writer.hpp"
#include "geometry/stone.hpp"
#include "trace/ray_list.hpp"

namespace gem::tables_test {

inline glm::dmat3 rotation_y(double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    // Columns: images of x, y, z under a right-handed turn about +y.
    return glm::dmat3{{c, 0.0, -s}, {0.0, 1.0, 0.0}, {s, 0.0, c}};
}

// C_nv about +y written out by hand: n turns, then the n mirrors turn·(x → -x).
inline std::vector<glm::dmat3> cnv(int n) {
    std::vector<glm::dmat3> group;
    const glm::dmat3 mirror_x{{-1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
    for (int k = 0; k < n; ++k) group.push_back(rotation_y(2.0 * std::numbers::pi * k / n));
    for (int k = 0; k < n; ++k)
        group.push_back(rotation_y(2.0 * std::numbers::pi * k / n) * mirror_x);
    return group;
}

inline glm::dvec3 random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    for (;;) {
        const glm::dvec3 v{normal(rng), normal(rng), normal(rng)};
        if (glm::length(v) > 1e-6) return glm::normalize(v);
    }
}

// A 6 × 3 × 4 mm box centred on the origin, with facets, loops and triangles written out,
// its symmetry C2v about y {identity, half turn, two mirrors}, and a sapphire-like material.
inline Stone box_stone() {
    Stone s;
    s.name = "test box";
    const double x = 3.0, y = 1.5, z = 2.0;
    s.vertices = {{-x, -y, -z}, {x, -y, -z}, {x, y, -z}, {-x, y, -z},
                  {-x, -y, z},  {x, -y, z},  {x, y, z},  {-x, y, z}};
    struct F {
        glm::dvec3 n;
        double d;
        std::vector<std::uint32_t> loop;
        FacetKind kind;
    };
    const std::vector<F> faces = {{{0, 0, -1}, z, {0, 3, 2, 1}, FacetKind::girdle},
                                  {{0, 0, 1}, z, {4, 5, 6, 7}, FacetKind::girdle},
                                  {{-1, 0, 0}, x, {0, 4, 7, 3}, FacetKind::girdle},
                                  {{1, 0, 0}, x, {1, 2, 6, 5}, FacetKind::girdle},
                                  {{0, -1, 0}, y, {0, 1, 5, 4}, FacetKind::pavilion},
                                  {{0, 1, 0}, y, {3, 7, 6, 2}, FacetKind::table}};
    for (std::size_t i = 0; i < faces.size(); ++i) {
        Facet f;
        f.plane = {faces[i].n, faces[i].d};
        f.loop = faces[i].loop;
        f.kind = faces[i].kind;
        f.name = "face " + std::to_string(i);
        s.facets.push_back(f);
        s.triangles.push_back({{f.loop[0], f.loop[1], f.loop[2]}, static_cast<std::uint32_t>(i)});
        s.triangles.push_back({{f.loop[0], f.loop[2], f.loop[3]}, static_cast<std::uint32_t>(i)});
    }
    s.symmetry = {glm::dmat3(1.0), rotation_y(std::numbers::pi),
                  glm::dmat3{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                  glm::dmat3{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}};
    s.material.name = "test sapphire";
    s.material.dispersion.kind = Dispersion::Kind::cauchy;
    s.material.dispersion.coef = {1.7516, 0.0061};
    s.material.body_colour = {0.2, 0.3, 0.9};
    s.material.absorption_per_mm = {0.5, 0.25, 0.01};
    return s;
}

inline TracedRay random_ray(std::mt19937_64& rng, double min_weight) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    TracedRay r;
    r.origin = {-3.0 + 6.0 * unit(rng), -1.5 + 3.0 * unit(rng), -2.0 + 4.0 * unit(rng)};
    r.direction = random_unit(rng);
    r.weight = min_weight * std::pow(1.0 / min_weight, unit(rng));  // log-uniform
    r.path_mm = 30.0 * unit(rng);
    r.bounces = static_cast<std::uint16_t>(rng() % 13);
    r.facet = static_cast<std::uint32_t>(rng() % 6);
    return r;
}

// side² random ray-lists seeded by (seed, view, level): about 60 % hit, up to 6 exits, some
// lighter than 1e-4 (dropped by the default threshold).
inline std::vector<RayList> random_lists(std::uint64_t seed, std::uint32_t side) {
    std::mt19937_64 rng(seed);
    std::vector<RayList> lists(static_cast<std::size_t>(side) * side);
    for (RayList& list : lists) {
        if (rng() % 10 < 4) continue;
        list.hit = true;
        list.reflected = random_ray(rng, 1e-3);
        list.reflected.path_mm = 0.0;
        const int exits = static_cast<int>(rng() % 7);
        for (int e = 0; e < exits; ++e) list.exits.push_back(random_ray(rng, 1e-6));
        list.truncated_weight = 1e-3 * static_cast<double>(rng() % 100);
    }
    return lists;
}

inline std::vector<glm::dvec3> random_derivatives(const std::vector<RayList>& lists,
                                                  std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> d(-2.0, 2.0);
    std::vector<glm::dvec3> out;
    for (const RayList& list : lists) {
        if (!list.hit) continue;
        for (std::size_t e = 0; e < list.exits.size(); ++e) out.push_back({d(rng), d(rng), d(rng)});
    }
    return out;
}

inline std::uint64_t chunk_seed(std::uint32_t view, std::uint32_t level) {
    return 1000003ull * view + 7919ull * level + 17ull;
}

struct SmallDatabase {
    Stone stone = box_stone();
    CameraModel camera{CameraModel::Kind::perspective, 40.0, 7.0};
    BuildParams params;
    ViewGrid grid;
};

inline SmallDatabase small_database(bool dispersion) {
    SmallDatabase db;
    db.params.levels = {8, 16};
    db.params.grid.spacing_rad = 0.45;
    db.params.grid.min_elevation_rad = -0.3;
    db.params.dispersion = dispersion;
    db.grid = ViewGrid::build(db.params.grid, db.stone.symmetry).value();
    return db;
}

inline Result<WriteSummary> write_small(const std::filesystem::path& path, const SmallDatabase& db,
                                        unsigned threads = 1) {
    TraceViewFn trace = [&](std::uint32_t view, std::uint32_t level) {
        return random_lists(chunk_seed(view, level), db.params.levels[level]);
    };
    TraceDerivativesFn derivatives = [](std::uint32_t view, std::uint32_t level,
                                        const std::vector<RayList>& lists) {
        return random_derivatives(lists, chunk_seed(view, level) + 1);
    };
    WriteOptions options;
    options.threads = threads;
    return write_database(path, db.stone, db.camera, db.params, db.grid, trace,
                          db.params.dispersion ? derivatives : TraceDerivativesFn{}, options);
}

// CTest runs tests as separate processes in parallel; the process id keeps one test from
// rewriting a file that another has memory-mapped (which would end it with SIGBUS).
inline std::filesystem::path artifact_dir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(GEM_ARTIFACT_DIR) / "tables" /
                                      (name + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
}

}  // namespace gem::tables_test
