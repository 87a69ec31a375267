// Pieces as web and CAD tools pass them on: the halo written here, then re-packed by gltfpack
// (Debian's, as a shop's web designer would run it) plainly, with EXT_mesh_gpu_instancing, with
// EXT_meshopt_compression, and quantised (KHR_mesh_quantization) at 16 and at gltfpack's
// default 14 bits. Each is read back to the same stones where they were: 23 of 2 kinds, every
// corner within the file's rounding, every facet of the cut, convex.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "../support/piece_corners.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/gltf_piece_writer.hpp"
#include "piece/piece_file.hpp"

namespace gem {
namespace {

namespace fs = std::filesystem;

struct Packing {
    const char* name;
    const char* options;
    double rounding_mm;  // how far the packing may move a corner
};

class Gltfpack : public testing::TestWithParam<Packing> {};

using test_support::corner_gap;

TEST_P(Gltfpack, TheHaloComesBackAsItsStones) {
    if (std::system("command -v gltfpack > /dev/null 2>&1") != 0) {
        GTEST_SKIP() << "gltfpack is not installed (deps/debian-packages.txt)";
    }
    const Packing& packing = GetParam();
    auto halo = load_piece(fs::path(GEM_CONFIG_DIR) / "pieces" / "halo.toml");
    ASSERT_TRUE(halo) << halo.error();
    const fs::path dir = fs::path(GEM_ARTIFACT_DIR) / "gltfpack";
    fs::create_directories(dir);
    const fs::path written = dir / "halo.glb", packed = dir / (std::string(packing.name) + ".glb");
    ASSERT_TRUE(write_piece_glb(halo.value(), written));
    const std::string command = "gltfpack -i '" + written.string() + "' -o '" + packed.string() +
                                "' " + packing.options + " > '" + packed.string() + ".log' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;

    std::vector<std::string> log;
    auto read = load_gltf_piece(packed, &log);
    ASSERT_TRUE(read) << read.error();
    const Piece& a = halo.value();
    const Piece& b = read.value();
    ASSERT_EQ(b.stones.size(), a.stones.size());
    EXPECT_EQ(b.kinds.size(), a.kinds.size());
    for (std::size_t i = 0; i < a.stones.size(); ++i) {
        EXPECT_LT(corner_gap(a, b, i), packing.rounding_mm) << a.stones[i].role;
        EXPECT_EQ(b.stone_of(i).facets.size(), a.stone_of(i).facets.size()) << a.stones[i].role;
        EXPECT_TRUE(b.stone_of(i).convex) << a.stones[i].role;
    }
    for (std::size_t k = 0; k < b.kinds.size(); ++k) {
        EXPECT_EQ(b.kinds[k].material.name, "diamond");
        EXPECT_DOUBLE_EQ(b.kinds[k].material.index(486.1), a.kinds[0].material.index(486.1));
    }
}

// The ring spans 24.5 mm of positions: 14 bits are 1.5 µm steps, 16 bits 0.4 µm (gltfpack makes
// one grid for the whole scene); its instances' float rotations move corners by 23 nm.
INSTANTIATE_TEST_SUITE_P(
    Packings, Gltfpack,
    testing::Values(Packing{"plain", "-noq", 1e-5}, Packing{"instanced", "-noq -mi", 1e-4},
                    Packing{"meshopt", "-noq -c", 1e-5}, Packing{"meshopt16", "-c -vp 16", 1e-3},
                    Packing{"quantised14", "", 3e-3}),
    [](const testing::TestParamInfo<Packing>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace gem
