// Writes the fuzz seed corpus: a tiny valid database (an octahedron traced for real at 2 and
// 4 pixels a side over a coarse grid), the same with dispersion, and damaged copies of it —
// a flipped byte in the header, a section and a payload, truncations, a stripped magic — so
// the fuzzer starts from inputs that reach every stage of the reader. Given a second folder, it
// writes the glTF reader's seeds there: the octahedron as a named stone on a metal plate (a
// piece the reader accepts), with a transmissive material and without, and damaged copies.
// Given a third, the model readers' seeds (model_seeds.hpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "../support/cad_corpus.hpp"
#include "../support/draco_mesh.hpp"
#include "../support/glb_writer.hpp"
#include "gemdb/writer.hpp"
#include "model_seeds.hpp"
#include "optics/material.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/gltf_piece_writer.hpp"
#include "trace/tracer.hpp"

namespace {

using Bytes = std::vector<char>;

// A regular octahedron of half-diagonal 1.5 mm, vertices on the axes; mirror-symmetric in x.
gem::Stone octahedron() {
    const double a = 1.5;
    gem::Stone s;
    s.name = "fuzz octahedron";
    s.vertices = {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}};
    for (int sx : {1, -1}) {
        for (int sy : {1, -1}) {
            for (int sz : {1, -1}) {
                gem::Facet f;
                f.plane.n = glm::normalize(glm::dvec3(sx, sy, sz));
                f.plane.d = a / std::sqrt(3.0);
                const std::uint32_t x = sx > 0 ? 0 : 1, y = sy > 0 ? 2 : 3, z = sz > 0 ? 4 : 5;
                // (x, y, z) runs counter-clockwise seen from outside when sx·sy·sz > 0.
                f.loop = sx * sy * sz > 0 ? std::vector<std::uint32_t>{x, y, z}
                                          : std::vector<std::uint32_t>{x, z, y};
                f.kind = sy > 0 ? gem::FacetKind::crown : gem::FacetKind::pavilion;
                f.name = "face";
                const auto index = static_cast<std::uint32_t>(s.facets.size());
                s.triangles.push_back({{f.loop[0], f.loop[1], f.loop[2]}, index});
                s.facets.push_back(f);
            }
        }
    }
    s.symmetry = {glm::dmat3(1.0), glm::dmat3{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    s.material = gem::find_material("diamond").value();
    return s;
}

bool write_valid(const std::filesystem::path& path, bool dispersion) {
    const gem::Stone stone = octahedron();
    gem::CameraModel camera;
    camera.field_mm = 3.5;
    gem::BuildParams params;
    params.levels = {2, 4};
    params.grid.spacing_rad = 0.9;
    params.dispersion = dispersion;
    auto built = gem::ViewGrid::build(params.grid, stone.symmetry);
    if (!built) {
        std::fprintf(stderr, "gem_fuzz_seeds: %s\n", built.error().c_str());
        return false;
    }
    const gem::ViewGrid& grid = built.value();
    const gem::Tracer tracer(stone);
    gem::TraceViewFn trace = [&](std::uint32_t view, std::uint32_t level) {
        const std::uint32_t side = params.levels[level];
        std::vector<gem::RayList> lists(side * side);
        for (std::uint32_t p = 0; p < side * side; ++p) {
            const gem::Ray ray =
                gem::camera_ray(camera, grid.basis(view),
                                gem::pixel_centre(p % side, p / side, side, camera.field_mm));
            tracer.trace(ray, stone.material.index(), gem::TraceSettings{}, lists[p]);
        }
        return lists;
    };
    gem::TraceDerivativesFn derivatives = [](std::uint32_t, std::uint32_t,
                                             const std::vector<gem::RayList>& lists) {
        std::vector<glm::dvec3> d;
        for (const gem::RayList& list : lists)
            d.resize(d.size() + list.exits.size(), {0.1, -0.2, 0.3});
        return d;
    };
    auto written = gem::write_database(path, stone, camera, params, grid, trace,
                                       dispersion ? derivatives : gem::TraceDerivativesFn{});
    if (!written) std::fprintf(stderr, "gem_fuzz_seeds: %s\n", written.error().c_str());
    return written.ok();
}

Bytes read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const std::filesystem::path& path, const Bytes& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The octahedron, in metres, standing on its lower corner 0.05 mm above a plate of metal.
gem::test_support::Glb octahedron_piece(bool transmissive) {
    const gem::Stone s = octahedron();
    gem::test_support::Glb glb;
    std::vector<glm::dvec3> corners;
    for (const glm::dvec3& v : s.vertices) corners.push_back((v + glm::dvec3(0, 1.5, 0)) / 1000.0);
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (const gem::MeshTriangle& t : s.triangles) triangles.push_back(t.v);
    int material = -1;
    if (transmissive) {
        material = glb.material({{"name", "Gem"},
                                 {"extensions",
                                  {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                   {"KHR_materials_ior", {{"ior", 2.42}}}}}});
    }
    glb.node({{"name", "Diamond_1"}, {"mesh", glb.mesh("stone", corners, triangles, material)}});
    const double t = -0.05e-3, b = -1.05e-3, w = 3e-3;
    std::vector<glm::dvec3> p;
    for (int i = 0; i < 8; ++i) p.push_back({i & 1 ? w : -w, i & 2 ? t : b, i & 4 ? w : -w});
    const std::vector<std::array<std::uint32_t, 3>> faces = {
        {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
        {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    glb.node({{"name", "Shank"}, {"mesh", glb.mesh("shank", p, faces, -1)}});
    return glb;
}

void write_gltf_seeds(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    octahedron_piece(true).write(dir / "valid.glb");
    octahedron_piece(false).write(dir / "by_name.glb");
    const Bytes valid = read(dir / "valid.glb");
    write(dir / "truncated_half.glb", Bytes(valid.begin(), valid.begin() + valid.size() / 2));
    Bytes flipped = valid;
    flipped[valid.size() - 5] = static_cast<char>(flipped[valid.size() - 5] ^ 0x5A);
    write(dir / "buffer_flip.glb", flipped);
    int seeds = 4;
    // The same piece as the project writes pieces (normals, the gem extensions), and that
    // file compressed by meshopt and quantised as web tools do, where gltfpack is installed.
    auto piece = gem::load_gltf_piece(dir / "valid.glb");
    if (!piece || !gem::write_piece_glb(piece.value(), dir / "written.glb")) {
        std::fprintf(stderr, "gem_fuzz_seeds: the seed piece does not read back: %s\n",
                     piece ? "not written" : piece.error().c_str());
        std::exit(1);
    }
    ++seeds;
    // Its stone compressed with Draco at 14 bits, as web exports come.
    {
        const gem::Stone s = octahedron();
        gem::test_support::Glb glb;
        std::vector<glm::dvec3> corners;
        for (const glm::dvec3& v : s.vertices) {
            corners.push_back((v + glm::dvec3(0, 1.5, 0)) / 1000.0);
        }
        std::vector<std::array<std::uint32_t, 3>> triangles;
        for (const gem::MeshTriangle& t : s.triangles) triangles.push_back(t.v);
        const int mesh = gem::test_support::draco_mesh(glb, "stone", corners, triangles, -1, 14);
        glb.node({{"name", "Diamond_1"}, {"mesh", mesh}});
        glb.write(dir / "draco.glb");
        ++seeds;
    }
    const std::string packed = (dir / "packed.glb").string();
    const std::string pack = "gltfpack -c -i '" + (dir / "written.glb").string() + "' -o '" +
                             packed + "' > /dev/null 2>&1";
    if (std::system(pack.c_str()) == 0) {
        ++seeds;
    } else {
        std::printf("gem_fuzz_seeds: no meshopt seed (gltfpack did not run)\n");
    }
    // The corpus of files made as other tools make them (cad_corpus.hpp), all but the large
    // ones: a seed of megabytes slows every mutation.
    const std::filesystem::path cad = dir / "cad-corpus";
    for (const auto& f : gem::test_support::cad::write_corpus(cad)) {
        if (std::filesystem::file_size(f.path) > 512 * 1024) continue;
        std::filesystem::copy_file(f.path, dir / ("cad-" + f.name),
                                   std::filesystem::copy_options::overwrite_existing);
        ++seeds;
    }
    std::filesystem::remove_all(cad);
    std::printf("gem_fuzz_seeds: wrote %d glTF seeds to %s\n", seeds, dir.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 4) {
        std::fprintf(stderr, "usage: gem_fuzz_seeds DIR [GLTF_DIR [MODEL_DIR]]\n");
        return 2;
    }
    if (argc >= 3) write_gltf_seeds(argv[2]);
    if (argc == 4) {
        const int models = gem::fuzz::write_model_seeds(argv[3]);
        if (models < 0) return 1;
        std::printf("gem_fuzz_seeds: wrote %d model seeds to %s\n", models, argv[3]);
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    if (!write_valid(dir / "valid.gemdb", false)) return 1;
    if (!write_valid(dir / "valid_dispersion.gemdb", true)) return 1;
    const Bytes valid = read(dir / "valid.gemdb");
    if (valid.size() < 400) return 1;

    auto flipped = [&](std::size_t at) {
        Bytes b = valid;
        b[at] = static_cast<char>(b[at] ^ 0x5A);
        return b;
    };
    write(dir / "header_flip.gemdb", flipped(20));
    write(dir / "section_flip.gemdb", flipped(300));
    write(dir / "payload_flip.gemdb", flipped(valid.size() - 3));
    write(dir / "truncated_tail.gemdb", Bytes(valid.begin(), valid.end() - 7));
    write(dir / "truncated_half.gemdb", Bytes(valid.begin(), valid.begin() + valid.size() / 2));
    write(dir / "magic_only.gemdb", Bytes(valid.begin(), valid.begin() + 8));
    Bytes stripped = valid;
    stripped[0] = static_cast<char>(stripped[0] & 0x7F);
    write(dir / "magic_stripped.gemdb", stripped);
    std::printf("gem_fuzz_seeds: wrote 9 seeds to %s\n", dir.c_str());
    return 0;
}
