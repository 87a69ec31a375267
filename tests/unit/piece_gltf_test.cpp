// Pieces read from glTF 2.0 files made here as CAD exports make them: written byte by byte
// from JSON (nlohmann) and a binary chunk, without the library the reader uses, and checked
// against the stones they were made from (their corners, facet counts and placements), so the
// reader's units, transforms, instancing, mirroring, merged meshes, materials and the ways a
// stone is recognised are each tested; and a damaged or unsupported file gives one message.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "../support/draco_mesh.hpp"
#include "../support/glb_writer.hpp"
#include "../support/piece_corners.hpp"
#include "geometry/cuts.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/piece_file.hpp"

namespace gem {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test_support::corner_error;
using test_support::Glb;

Stone brilliant(double width_mm) {
    CutParams p = default_cut_params(CutShape::round_brilliant);
    p.width_mm = width_mm;
    return make_cut(p, find_material("diamond").value()).value();
}

// A stone's corners and triangles, in metres.
std::vector<glm::dvec3> metres(const Stone& s, glm::dvec3 offset_mm = glm::dvec3(0.0)) {
    std::vector<glm::dvec3> out;
    for (const glm::dvec3& v : s.vertices) out.push_back((v + offset_mm) / 1000.0);
    return out;
}
std::vector<std::array<std::uint32_t, 3>> triangles(const Stone& s) {
    std::vector<std::array<std::uint32_t, 3>> out;
    for (const MeshTriangle& t : s.triangles) out.push_back(t.v);
    return out;
}

// A plate of metal under the stones: its top 0.05 mm below `top_mm`, as a seat holds a culet.
void add_plate(Glb& glb, double top_mm, int material) {
    const double t = (top_mm - 0.05) / 1000.0, b = t - 0.001, w = 0.05;
    std::vector<glm::dvec3> p;
    for (int i = 0; i < 8; ++i) p.push_back({i & 1 ? w : -w, i & 2 ? t : b, i & 4 ? w : -w});
    const std::vector<std::array<std::uint32_t, 3>> faces = {
        {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
        {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    glb.node({{"name", "Shank"}, {"mesh", glb.mesh("shank", p, faces, material)}});
}

double culet_y(const Stone& s) {
    double y = HUGE_VAL;
    for (const glm::dvec3& v : s.vertices) y = std::min(y, v.y);
    return y;
}

fs::path artifact(const std::string& name) {
    const fs::path dir = fs::path(GEM_ARTIFACT_DIR) / "gltf";
    fs::create_directories(dir);
    return dir / name;
}

TEST(GltfPiece, StonesAndMetalAsACadExportWritesThem) {
    const Stone big = brilliant(2.0), small = brilliant(1.5);
    Glb glb;
    const int gold = glb.material({{"name", "Yellow gold"},
                                   {"pbrMetallicRoughness",
                                    {{"baseColorFactor", {1.0, 0.78, 0.34, 1.0}},
                                     {"metallicFactor", 1.0},
                                     {"roughnessFactor", 0.2}}}});
    const int gem = glb.material({{"name", "Gem"},
                                  {"extensions",
                                   {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                    {"KHR_materials_ior", {{"ior", 2.2}}},
                                    {"KHR_materials_dispersion", {{"dispersion", 0.5}}}}}});
    const int paint = glb.material({{"name", "Paint 3"}});
    // The big stone's mesh used by two nodes, turned about y; the small one by a node named as
    // CAD names stones, and mirrored by another.
    const int big_mesh = glb.mesh("Round 2mm", metres(big), triangles(big), gem);
    const int small_mesh = glb.mesh("obj_17", metres(small), triangles(small), paint);
    const double lift = -culet_y(big);  // every culet at the plate
    const double small_lift = -culet_y(small);
    const auto about_y = [](double deg) {
        const double h = deg * std::numbers::pi / 360.0;
        return json::array({0.0, std::sin(h), 0.0, std::cos(h)});
    };
    glb.node({{"name", "Diamond_1"},
              {"mesh", big_mesh},
              {"translation", {-0.003, lift / 1000.0, 0.0}},
              {"rotation", about_y(30.0)}});
    glb.node({{"name", "Diamond_2"},
              {"mesh", big_mesh},
              {"translation", {0.0, lift / 1000.0, 0.0}},
              {"rotation", about_y(75.0)}});
    glb.node({{"name", "dia045"},
              {"mesh", small_mesh},
              {"translation", {0.003, small_lift / 1000.0, 0.0}}});
    glb.node({{"name", "Gem 01"},
              {"mesh", small_mesh},
              {"translation", {0.0055, small_lift / 1000.0, 0.0}},
              {"scale", {-1.0, 1.0, 1.0}}});
    add_plate(glb, 0.0, gold);
    const fs::path file = artifact("cad-like.glb");
    glb.write(file);

    std::vector<std::string> log;
    auto read = load_piece(file, &log);
    ASSERT_TRUE(read) << read.error();
    const Piece& piece = read.value();
    for (const std::string& line : log) std::printf("%s\n", line.c_str());
    ASSERT_EQ(piece.stones.size(), 4u);
    // One kind for the big stone's two placements, one for the small one, one for its mirror.
    EXPECT_EQ(piece.kinds.size(), 3u);
    EXPECT_EQ(describe(piece), "piece cad-like: 4 stones (3 distinct), 12 metal triangles");
    // Each stone where its node put it, corner for corner (mm), found by its position.
    const auto expect_at = [&](glm::dvec3 centre_mm, const Stone& stone, double turn_deg,
                               bool mirror) {
        centre_mm -= piece.file_origin_mm;  // the centre stone is put at the origin
        std::vector<glm::dvec3> corners;
        const double a = turn_deg * std::numbers::pi / 180.0;
        for (glm::dvec3 v : stone.vertices) {
            if (mirror) v.x = -v.x;
            corners.push_back(centre_mm + glm::dvec3(std::cos(a) * v.x + std::sin(a) * v.z, v.y,
                                                     -std::sin(a) * v.x + std::cos(a) * v.z));
        }
        std::size_t nearest = 0;
        for (std::size_t i = 1; i < piece.stones.size(); ++i) {
            if (glm::length(piece.stones[i].placement.position - centre_mm) <
                glm::length(piece.stones[nearest].placement.position - centre_mm)) {
                nearest = i;
            }
        }
        EXPECT_LT(corner_error(piece, nearest, corners), 1e-4) << piece.stones[nearest].role;
        const Stone& kind = piece.kinds[piece.stones[nearest].kind];
        EXPECT_EQ(kind.facets.size(), stone.facets.size()) << piece.stones[nearest].role;
        EXPECT_TRUE(kind.convex) << piece.stones[nearest].role;
        return kind;
    };
    const Stone first = expect_at({-3.0, lift, 0.0}, big, 30.0, false);
    expect_at({0.0, lift, 0.0}, big, 75.0, false);
    const Stone by_name = expect_at({3.0, small_lift, 0.0}, small, 0.0, false);
    expect_at({5.5, small_lift, 0.0}, small, 0.0, true);
    // The big stones are the centre (the first stone).
    EXPECT_EQ(piece.kinds[piece.stones[0].kind].facets.size(), big.facets.size());
    // The gem extensions: n_d 2.2; 20 / 0.5 = Abbe number 40, so n_F − n_C = (n_d − 1) / 40.
    EXPECT_NEAR(first.material.index(587.6), 2.2, 1e-9);
    EXPECT_NEAR(first.material.index(486.1) - first.material.index(656.3), 1.2 / 40.0, 1e-9);
    // Recognised by name only: diamond, the default.
    EXPECT_NEAR(by_name.material.index(), find_material("diamond")->index(), 1e-12);
    // The metal: F0 is the base colour of a metallic material.
    EXPECT_NEAR(piece.metal.f0.y, 0.78f, 1e-6f);
    EXPECT_NEAR(piece.metal.roughness, 0.2f, 1e-6f);
    // Each stone says how it was recognised, and then the metal is described.
    ASSERT_EQ(log.size(), 4u);
    EXPECT_NE(log[3].find("metal: 12 triangles in 1 material(s), drawn as 'Yellow gold'"),
              std::string::npos)
        << log[3];
    EXPECT_NE(log[0].find("its material 'Gem' is transmissive"), std::string::npos) << log[0];
    EXPECT_NE(log[1].find("its node's name 'dia045'"), std::string::npos) << log[1];
    EXPECT_NE(log[2].find("its node's name 'Gem 01'"), std::string::npos) << log[2];
}

// A stone stored in float32 metres far from the file's origin has its corners rounded by up
// to 2^-24 of their distance: its facets must still come out as the cut's, convex.
TEST(GltfPiece, FacetsSurviveFloatRoundingFarFromTheOrigin) {
    const Stone s = brilliant(1.5);
    for (double off : {0.0, 1.0, 3.0, 10.0, 30.0}) {
        Glb glb;
        glb.node({{"name", "Diamond"},
                  {"mesh", glb.mesh("d", metres(s, {off, -culet_y(s), 0}), triangles(s), -1)}});
        add_plate(glb, 0.0, -1);
        const fs::path file = artifact("far.glb");
        glb.write(file);
        auto read = load_piece(file);
        ASSERT_TRUE(read) << read.error();
        const Stone& kind = read.value().kinds[0];
        EXPECT_EQ(kind.facets.size(), s.facets.size()) << off << " mm from the origin";
        EXPECT_TRUE(kind.convex) << off << " mm from the origin";
    }
}

TEST(GltfPiece, StonesMergedIntoOneMeshComeApart) {
    const Stone s = brilliant(1.5);
    std::vector<glm::dvec3> p = metres(s, {-1.0, -culet_y(s), 0.0});
    auto t = triangles(s);
    const auto second = metres(s, {1.0, -culet_y(s), 0.0});
    const auto base = static_cast<std::uint32_t>(p.size());
    p.insert(p.end(), second.begin(), second.end());
    for (auto tri : triangles(s)) t.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    Glb glb;
    glb.node({{"name", "Pave diamonds"}, {"mesh", glb.mesh("merged", p, t, -1)}});
    add_plate(glb, 0.0, -1);
    const fs::path file = artifact("merged.glb");
    glb.write(file);
    auto read = load_piece(file);
    ASSERT_TRUE(read) << read.error();
    ASSERT_EQ(read.value().stones.size(), 2u);
    for (const PieceStone& stone : read.value().stones) {
        const glm::dvec3 in_file = stone.placement.position + read.value().file_origin_mm;
        EXPECT_NEAR(std::abs(in_file.x), 1.0, 1e-6);
        EXPECT_EQ(read.value().kinds[stone.kind].facets.size(), s.facets.size());
    }
}

// Stones compressed with Draco (KHR_draco_mesh_compression), as jewellery exports for the web
// come: Draco quantises a mesh's positions to a grid over its bounds, and the reader takes that
// grid's step into its facet tolerance. Each 1.5 mm brilliant keeps its 89 facets, convex,
// within a step of where it was: three stones merged into one mesh at Blender's 14 bits, and one
// stone a mesh at three.js's 11 bits. (Three merged at 11 bits, a 2.7 µm grid, keep 86 of
// their 89 facets, still convex: docs/gltf.md.)
TEST(GltfPiece, DracoCompressedStonesComeBackWithTheirFacets) {
    const Stone s = brilliant(1.5);
    for (const auto& [bits, stones] : {std::pair{14, 3}, std::pair{11, 1}}) {
        std::vector<glm::dvec3> p;
        std::vector<std::array<std::uint32_t, 3>> t;
        for (int k = 0; k < stones; ++k) {
            const auto base = static_cast<std::uint32_t>(p.size());
            const auto corners = metres(s, {2.0 * k, -culet_y(s), 0.0});
            p.insert(p.end(), corners.begin(), corners.end());
            for (auto tri : triangles(s))
                t.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
        }
        Glb glb;
        const int mesh = test_support::draco_mesh(glb, "pave", p, t, -1, bits);
        ASSERT_GE(mesh, 0);
        glb.node({{"name", "Diamonds"}, {"mesh", mesh}});
        add_plate(glb, 0.0, -1);
        const fs::path file = artifact("draco.glb");
        glb.write(file);
        auto read = load_piece(file);
        ASSERT_TRUE(read) << read.error();
        ASSERT_EQ(read.value().stones.size(), std::size_t(stones));
        // The grid: the mesh's span over 2^bits − 1 steps.
        const double step_mm = (1.5 + 2.0 * (stones - 1)) / (std::ldexp(1.0, bits) - 1.0);
        for (const PieceStone& stone : read.value().stones) {
            const Stone& kind = read.value().kinds[stone.kind];
            EXPECT_EQ(kind.facets.size(), s.facets.size()) << bits << " bits";
            EXPECT_TRUE(kind.convex) << bits << " bits";
            const glm::dvec3 origin = read.value().file_origin_mm;
            const double x = std::round((stone.placement.position.x + origin.x) / 2.0) * 2.0;
            double worst = 0.0;
            for (const glm::dvec3& v : s.vertices) {
                const glm::dvec3 want = v + glm::dvec3(x, -culet_y(s), 0.0) - origin;
                double nearest = HUGE_VAL;
                for (const glm::dvec3& w : kind.vertices) {
                    nearest = std::min(nearest, glm::length(stone.placement.to_piece(w) - want));
                }
                worst = std::max(worst, nearest);
            }
            EXPECT_LT(worst, step_mm) << bits << " bits";
        }
    }
}

// A manifest beside the file (RING.glb.toml) wins over the file's materials and names: it makes
// a part named without a gem word a ruby, and keeps a part whose name says "diamond" metal.
// Without it the same file is read by its names (the plate named a diamond is taken for the
// stone, the brilliant for metal); a bad manifest line is named by file, line and key.
TEST(GltfPiece, AManifestBesideTheFileWinsOverItsNames) {
    const Stone s = brilliant(1.5);
    Glb glb;
    glb.node({{"name", "Body_012"},
              {"mesh", glb.mesh("Body_012", metres(s, {0, -culet_y(s), 0}), triangles(s), -1)}});
    add_plate(glb, 0.0, -1);
    glb.doc()["nodes"][1]["name"] = "Diamond setting";
    const fs::path file = artifact("manifest.glb");
    glb.write(file);
    fs::path manifest = file;
    manifest += ".toml";
    fs::remove(manifest);
    // By its names alone nothing is a stone: "Diamond setting" says both stone and metal, and
    // Body_012 says nothing.
    auto by_names = load_piece(file);
    ASSERT_FALSE(by_names);
    EXPECT_NE(by_names.error().find("no stone found"), std::string::npos) << by_names.error();

    std::ofstream(manifest) << "[[stone]]\nname = \"Body_012\"\nmaterial = \"ruby\"\n\n"
                            << "[[metal]]\nname = \"Diamond setting\"\n";
    std::vector<std::string> log;
    auto read = load_gltf_piece(file, &log);
    ASSERT_TRUE(read) << read.error();
    ASSERT_EQ(read.value().stones.size(), 1u);
    EXPECT_EQ(read.value().kinds[0].material.name, "ruby");
    EXPECT_EQ(read.value().kinds[0].facets.size(), s.facets.size());
    ASSERT_EQ(log.size(), 2u);  // the stone, and the metal
    EXPECT_NE(
        log[0].find("the manifest manifest.glb.toml names it 'Body_012'; ruby (the manifest)"),
        std::string::npos)
        << log[0];

    std::ofstream(manifest) << "[[stone]]\nname = \"Body_012\"\nmaterial = \"kryptonite\"\n";
    auto bad = load_piece(file);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().find("manifest.glb.toml:3: stone.material: 'kryptonite' is not a "
                               "built-in material"),
              std::string::npos)
        << bad.error();
    fs::remove(manifest);
}

// One message each, naming the file and the fault.
TEST(GltfPiece, DamagedAndUnsupportedFilesAreOneMessage) {
    const Stone s = brilliant(1.5);
    const auto expect_error = [](const fs::path& file, const std::string& part) {
        auto read = load_piece(file);
        ASSERT_FALSE(read) << file;
        EXPECT_NE(read.error().find(file.string()), std::string::npos) << read.error();
        EXPECT_NE(read.error().find(part), std::string::npos) << read.error();
    };
    const auto good = [&] {
        Glb glb;
        glb.node({{"name", "Diamond"},
                  {"mesh", glb.mesh("d", metres(s, {0, -culet_y(s), 0}), triangles(s), -1)}});
        add_plate(glb, 0.0, -1);
        return glb;
    };
    const fs::path text = artifact("not-gltf.glb");
    std::ofstream(text) << "solid ring\nendsolid\n";
    expect_error(text, "not glTF");

    const fs::path whole = artifact("whole.glb");
    good().write(whole);
    std::ifstream in(whole, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const fs::path cut = artifact("truncated.glb");
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    expect_error(cut, "not read as glTF");
    const fs::path header = artifact("header-only.glb");
    std::ofstream(header, std::ios::binary) << bytes.substr(0, 16);
    expect_error(header, "truncated");

    Glb outside = good();
    outside.doc()["bufferViews"][0]["byteLength"] = 1 << 20;
    const fs::path far = artifact("outside.glb");
    outside.write(far);
    expect_error(far, "reaches outside its buffer");

    // Draco data that does not decode (plain floats).
    Glb draco = good();
    draco.doc()["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
        {"bufferView", 0}, {"attributes", {{"POSITION", 0}}}};
    const fs::path dracoed = artifact("draco-bad.glb");
    draco.write(dracoed);
    expect_error(dracoed, "(Draco): does not decode");

    // meshopt data that does not decode (plain floats), and a stride meshopt never writes.
    for (const auto& [stride, fault] :
         {std::pair{12, "does not decode"}, std::pair{6, "is not meshopt's"}}) {
        Glb packed = good();
        const json view = packed.doc()["bufferViews"][0];
        packed.doc()["bufferViews"][0]["extensions"]["EXT_meshopt_compression"] = {
            {"buffer", 0},      {"byteOffset", view["byteOffset"]},
            {"byteLength", 64}, {"byteStride", stride},
            {"count", 4},       {"mode", "ATTRIBUTES"}};
        packed.doc()["extensionsRequired"] = {"EXT_meshopt_compression"};
        const fs::path meshopt = artifact("meshopt.glb");
        packed.write(meshopt);
        expect_error(meshopt, fault);
    }

    Glb cycle = good();
    cycle.doc()["nodes"][0]["children"] = {1};
    cycle.doc()["nodes"][1]["children"] = {0};
    const fs::path loop = artifact("cycle.glb");
    cycle.write(loop);
    expect_error(loop, "reached twice");

    // A gem that lost a whole facet (its table) cannot be closed by its other facets' planes
    // (they would meet above it): its hole is filled. (One lost triangle is closed by the
    // planes: CatalogueValidate.Gltf...)
    Glb open;
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (const MeshTriangle& t : s.triangles) {
        if (s.facets[t.facet].kind != FacetKind::table) tris.push_back(t.v);
    }
    open.node(
        {{"name", "Diamond"}, {"mesh", open.mesh("d", metres(s, {0, -culet_y(s), 0}), tris, -1)}});
    add_plate(open, 0.0, -1);
    const fs::path holed = artifact("open.glb");
    open.write(holed);
    std::vector<std::string> log;
    auto filled = load_gltf_piece(holed, &log);
    ASSERT_TRUE(filled) << filled.error();
    EXPECT_EQ(filled.value().stone_of(0).facets.size(), s.facets.size());
    EXPECT_TRUE(std::any_of(log.begin(), log.end(), [](const std::string& l) {
        return l.find(
                   "node 'Diamond' (mesh 'd'): repaired; open (8 boundary edges): 1 hole "
                   "filled") != std::string::npos;
    })) << log.front();

    Glb bare;
    add_plate(bare, 0.0, -1);
    const fs::path metal = artifact("metal-only.glb");
    bare.write(metal);
    expect_error(metal, "no stone found");
}

}  // namespace
}  // namespace gem
