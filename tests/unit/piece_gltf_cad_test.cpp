// Pieces from glTF files made as other tools make them (support/cad_corpus.hpp): each class of
// file that real CAD and web-viewer exports were refused for now loads, repaired where it can
// be, with one warning line saying what was done; and what it makes is checked against what the
// file was made from (the cut's corners and facets, the metal's triangles, the material's
// numbers worked by hand).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "../support/cad_corpus.hpp"
#include "../support/piece_corners.hpp"
#include "geometry/mesh_repair.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/gltf_stone_evidence.hpp"
#include "piece/metal_simplify.hpp"
#include "piece/stone_shape.hpp"

namespace gem {
namespace {

namespace fs = std::filesystem;
namespace cad = test_support::cad;
using nlohmann::json;
using test_support::corner_error;

struct Loaded {
    Piece piece;
    std::vector<std::string> log;
};

const std::map<std::string, Loaded>& corpus() {
    static const std::map<std::string, Loaded> loaded = [] {
        std::map<std::string, Loaded> out;
        // A folder of the test's own: CTest runs each test as a process of its own, side by side.
        const fs::path dir = fs::path(GEM_ARTIFACT_DIR) / "gltf-cad" /
                             ::testing::UnitTest::GetInstance()->current_test_info()->name();
        for (const cad::CorpusFile& f : cad::write_corpus(dir)) {
            std::vector<std::string> log;
            auto piece = load_gltf_piece(f.path, &log);
            EXPECT_TRUE(piece) << f.name << ": " << (piece ? "" : piece.error());
            if (piece) out[f.name] = {std::move(piece).value(), std::move(log)};
        }
        return out;
    }();
    return loaded;
}

const Loaded& file(const std::string& name) {
    const auto it = corpus().find(name);
    if (it == corpus().end()) throw std::runtime_error(name + " did not load");
    return it->second;
}

// The warning lines holding `text`.
std::vector<std::string> warnings_with(const Loaded& l, const std::string& text) {
    std::vector<std::string> out;
    for (const std::string& line : l.log) {
        if (line.starts_with("warning: ") && line.find(text) != std::string::npos) {
            out.push_back(line);
        }
    }
    return out;
}

std::string all(const Loaded& l) {
    std::string out;
    for (const std::string& line : l.log) out += line + "\n";
    return out;
}

// The cut's corners, each taken by `to` (mm).
std::vector<glm::dvec3> placed(const Stone& cut, const std::function<glm::dvec3(glm::dvec3)>& to) {
    std::vector<glm::dvec3> out;
    for (const glm::dvec3& v : cut.vertices) out.push_back(to(v));
    return out;
}

// The centre stone read back as the 6.5 mm brilliant it was made from: every facet, convex.
void expect_the_brilliant(const Loaded& l) {
    const Stone cut = cad::round_brilliant(6.5);
    const Stone& stone = l.piece.stone_of(0);
    EXPECT_EQ(stone.facets.size(), cut.facets.size()) << all(l);
    EXPECT_TRUE(stone.convex);
}

// Where the reader puts a centre stone that the file's origin lies outside of (the finger's
// centre): its corners' centroid at the piece's origin.
glm::dvec3 centroid(const Stone& s) {
    glm::dvec3 c(0.0);
    for (const glm::dvec3& v : s.vertices) c += v;
    return c / static_cast<double>(s.vertices.size());
}

TEST(GltfCadCorpus, EveryFileLoads) {
    const fs::path dir = fs::path(GEM_ARTIFACT_DIR) / "gltf-cad" / "listed";
    for (const cad::CorpusFile& f : cad::write_corpus(dir)) {
        ASSERT_TRUE(corpus().contains(f.name)) << f.name;
        EXPECT_EQ(corpus().at(f.name).piece.stones.size(), static_cast<std::size_t>(f.stones))
            << f.name << "\n"
            << all(corpus().at(f.name));
    }
}

TEST(GltfCadCorpus, ALooseStoneIsAPieceWithAWarning) {
    const Loaded& l = file("loose-stone.glb");
    EXPECT_TRUE(l.piece.metal.positions.empty());
    EXPECT_EQ(warnings_with(l, "floats off its seat").size(), 1u) << all(l);
    expect_the_brilliant(l);
    // Its origin lies inside the stone: kept, so every corner is where the file has it.
    EXPECT_LT(corner_error(l.piece, 0, cad::round_brilliant(6.5).vertices), 1e-5);
}

TEST(GltfCadCorpus, PrismsBeforeABackdropAreStonesAndTheBackdropMetal) {
    const Loaded& l = file("prism-scene.glb");
    ASSERT_EQ(l.piece.stones.size(), 25u);
    for (const PieceStone& s : l.piece.stones) {
        EXPECT_EQ(l.piece.kinds[s.kind].facets.size(), 5u);
        EXPECT_TRUE(l.piece.kinds[s.kind].convex);
    }
    EXPECT_EQ(l.piece.metal.triangle_count(), 2u);  // the backdrop
    // Prism 7: n_d 1.55, dispersion 0.5 → V_d 40, so n_F − n_C = 0.55 / 40 (worked by hand).
    const auto seven = std::find_if(
        l.piece.stones.begin(), l.piece.stones.end(),
        [](const PieceStone& s) { return s.role.find("'Prism.7'") != std::string::npos; });
    ASSERT_NE(seven, l.piece.stones.end());
    const Material& m = l.piece.kinds[seven->kind].material;
    EXPECT_NEAR(m.index(587.6), 1.55, 1e-9);
    EXPECT_NEAR(m.index(486.1) - m.index(656.3), 0.55 / 40.0, 1e-9);
}

TEST(GltfCadCorpus, AnUncutSeatIsAWarningWithItsDepth) {
    const Loaded& l = file("uncut-seat.glb");
    const auto lines = warnings_with(l, "the metal cuts");
    ASSERT_EQ(lines.size(), 1u) << all(l);
    const double depth = std::stod(lines[0].substr(lines[0].find("cuts ") + 5));
    // The culet sinks 0.6 mm below the shank's top; the shank's polygon top sits at most its
    // sagitta below the circle, so the depth seen is 0.6 mm less that, within 0.01 mm.
    EXPECT_NEAR(depth, 0.6, 0.01);
    EXPECT_NE(lines[0].find("uncut-seat.glb"), std::string::npos);
}

TEST(GltfCadCorpus, LinesAndPointsAreSkippedWithAWarningEach) {
    const Loaded& l = file("curves-and-points.glb");
    EXPECT_EQ(warnings_with(l, "lines (mode 3) skipped").size(), 1u) << all(l);
    EXPECT_EQ(warnings_with(l, "points (mode 0) skipped").size(), 1u) << all(l);
    EXPECT_EQ(l.piece.metal.triangle_count(), cad::shank().triangle_count());
}

TEST(GltfCadCorpus, TrianglesWithNoAreaAreDroppedAndTheStoneKeepsItsFacets) {
    const Loaded& l = file("zero-area.glb");
    expect_the_brilliant(l);
    EXPECT_EQ(warnings_with(l, "1 triangle with no area dropped").size(), 1u) << all(l);
    EXPECT_EQ(warnings_with(l, "2 metal triangle(s) with no area dropped").size(), 1u) << all(l);
    EXPECT_EQ(l.piece.metal.triangle_count(), cad::shank().triangle_count());
}

TEST(GltfCadCorpus, AStoneMissingAWholeFacetIsClosedAsItWas) {
    const Loaded& l = file("open-stone.glb");
    expect_the_brilliant(l);
    const Stone cut = cad::round_brilliant(6.5);
    EXPECT_EQ(warnings_with(l, "1 hole filled").size(), 1u) << all(l);
    const glm::dvec3 c = centroid(cut);
    EXPECT_LT(corner_error(l.piece, 0, placed(cut, [&](glm::dvec3 p) { return p - c; })), 1e-5);
}

TEST(GltfCadCorpus, AShankWithAnIndexAndAClearCoatIsMetal) {
    const Loaded& l = file("ior-clearcoat-shank.glb");
    ASSERT_EQ(l.piece.stones.size(), 1u);
    EXPECT_EQ(l.piece.metal.triangle_count(), cad::shank(9.0, 1024, 64).triangle_count());
    EXPECT_GT(l.piece.metal.triangle_count(), 100000u);
    // Metallic 1: F0 is the base colour.
    EXPECT_NEAR(l.piece.metal.f0.y, 0.766f, 1e-6f);
    EXPECT_NEAR(l.piece.metal.roughness, 0.25f, 1e-6f);
    EXPECT_EQ(warnings_with(l, "clear coat is left out").size(), 1u) << all(l);
}

TEST(GltfCadCorpus, AVendorDiamondMaterialOnMergedStones) {
    const Loaded& l = file("webgi-merged-band.glb");
    ASSERT_EQ(l.piece.stones.size(), 52u);
    const Material& m = l.piece.stone_of(0).material;
    // refractiveIndex 2.6; dispersion 0.012 → n_F − n_C = 0.024 (docs/gltf.md), checked at the
    // F and C lines of the Cauchy form the reader builds.
    EXPECT_NEAR(m.index(587.6), 2.6, 1e-9);
    EXPECT_NEAR(m.index(486.1) - m.index(656.3), 0.024, 1e-9);
    EXPECT_EQ(m.body_colour, glm::dvec3(1.0));
    for (const PieceStone& s : l.piece.stones) {
        EXPECT_EQ(l.piece.kinds[s.kind].facets.size(), cad::round_brilliant(1.1).facets.size());
    }
    const std::string text = all(l);
    EXPECT_NE(text.find("carries WEBGI_materials_diamond (+3)"), std::string::npos) << text;
}

TEST(GltfCadCorpus, MillimetresAndZUpAreSeenAndTurned) {
    const Loaded& l = file("millimetres-z-up.glb");
    EXPECT_EQ(warnings_with(l, "read in millimetres").size(), 1u) << all(l);
    EXPECT_EQ(warnings_with(l, "the centre stone's table faced +z").size(), 1u) << all(l);
    // As the solitaire in metres and y up: the shank's outer radius 10 mm about x, the table up.
    // The centre stone at the origin, its table up; the shank's top 10 mm above the finger's
    // centre, which is the stone's lift below it.
    const Stone cut = cad::round_brilliant(6.5);
    const glm::dvec3 c = centroid(cut);
    EXPECT_LT(corner_error(l.piece, 0, placed(cut, [&](glm::dvec3 p) { return p - c; })), 1e-4);
    const double lift = 10.0 + cad::pavilion_depth(cut);
    float top = -1e9f;
    for (const glm::vec3& p : l.piece.metal.positions) top = std::max(top, p.y);
    EXPECT_NEAR(top, 10.0 - lift - c.y, 1e-3);
}

// A file the fuzzer made (tests/fixtures/gltf/): a stone of slivers whose splitting at a
// T-junction made slivers again, back and forth without end. It now reads in a moment, and is
// refused in one line: what is left of the stone encloses no volume.
TEST(GltfCadCorpus, SliversThatSplitIntoSliversEnd) {
    auto read = load_gltf_piece(fs::path(GEM_FIXTURES_DIR) / "gltf" /
                                "fuzz-slivers-split-back-and-forth.glb");
    ASSERT_FALSE(read);
    EXPECT_NE(read.error().find("encloses no volume"), std::string::npos) << read.error();
}

// WEBGI_materials_diamond's colour as its exporters write it: a number 0xRRGGBB or a string
// "#RRGGBB", sRGB; and isDiamond false says the material is not a gem.
TEST(GltfCadCorpus, AVendorDiamondsColourAndItsNo) {
    const Stone cut = cad::round_brilliant(2.0);
    const auto loose = [&](json webgi) {
        test_support::Glb glb;
        const int m = glb.material(
            {{"name", "Material_1"}, {"extensions", {{"WEBGI_materials_diamond", webgi}}}});
        const int mesh =
            glb.mesh_of("Object_1", json::array({cad::primitive(glb, cad::stone_soup(cut), m)}));
        glb.node({{"name", "Object_1"}, {"mesh", mesh}});
        const fs::path file = fs::path(GEM_ARTIFACT_DIR) / "gltf-cad" / "webgi-colour.glb";
        glb.write(file);
        return load_gltf_piece(file);
    };
    // 0x80 is 128: sRGB 0.50196 decodes to 0.21586 (IEC 61966-2-1, worked by hand).
    for (const json& colour : {json("#FF8000"), json(0xFF8000)}) {
        auto read = loose({{"color", colour}});
        ASSERT_TRUE(read) << read.error();
        const glm::dvec3 c = read.value().stone_of(0).material.body_colour;
        EXPECT_NEAR(c.x, 1.0, 1e-9) << colour;
        EXPECT_NEAR(c.y, 0.21586, 1e-5) << colour;
        EXPECT_NEAR(c.z, 0.0, 1e-9) << colour;
    }
    auto no = loose({{"isDiamond", false}, {"refractiveIndex", 2.4}});
    ASSERT_FALSE(no);
    EXPECT_NE(no.error().find("no stone found"), std::string::npos) << no.error();
}

// A corner far from the centre stone: a scene, or units the file does not say; and past a
// float's range in millimetres it would poison the boxes the GPU finds surfaces by
// (piece/sight_mesh.hpp; fuzz_gltf found a file whose corners came to infinity). Refused with
// the reach found. The same file with its shank 50 units away loads: 50 across is read as
// millimetres (millimetres_per_unit), and more than 400 as metres, so 1000 units are 1e6 mm.
TEST(GltfCadCorpus, AShankFarFromItsStoneIsRefusedWithItsReach) {
    const Stone cut = cad::round_brilliant(6.5);
    const auto with_shank_at = [&](double metres) {
        test_support::Glb glb;
        const int diamond = cad::transmissive(glb, "Diamond");
        const int gold = cad::gold(glb);
        cad::Soup band = cad::metal_soup(cad::shank());
        for (glm::dvec3& p : band.positions) p.x += metres;
        const int gem = glb.mesh_of(
            "Brilliant", json::array({cad::primitive(glb, cad::stone_soup(cut), diamond)}));
        const int ring = glb.mesh_of("Ring", json::array({cad::primitive(glb, band, gold)}));
        const int a = glb.child({{"name", "Diamond"}, {"mesh", gem}});
        const int b = glb.child({{"name", "Shank"}, {"mesh", ring}});
        glb.node({{"name", "Solitaire"}, {"children", {a, b}}});
        const fs::path file = fs::path(GEM_ARTIFACT_DIR) / "gltf-cad" / "far-shank.glb";
        glb.write(file);
        return load_gltf_piece(file);
    };
    auto near = with_shank_at(50.0);
    EXPECT_TRUE(near) << near.error();
    // 1e6 mm and the shank's 10 mm, in the reader's three significant digits.
    auto far = with_shank_at(1000.0);
    ASSERT_FALSE(far);
    EXPECT_NE(far.error().find("far-shank.glb: a corner of the piece lies 1e+06 mm from its "
                               "centre stone (at most 100000 mm"),
              std::string::npos)
        << far.error();
    // 1e36 m is a float in the file, and 1e39 mm is none.
    auto past = with_shank_at(1e36);
    ASSERT_FALSE(past);
    EXPECT_NE(past.error().find("not a finite number of millimetres"), std::string::npos)
        << past.error();
}

TEST(GltfStoneEvidence, SignsWeighAsDocumented) {
    import::GltfPart part;
    import::GltfMaterial m;
    m.name = "Material.002";
    m.extensions = {"KHR_materials_ior", "KHR_materials_clearcoat"};
    EXPECT_EQ(stone_evidence(part, &m).score, 1);  // an index alone does not make a stone
    part.node = "Diamond setting";                 // both words: neither
    EXPECT_EQ(stone_evidence(part, &m).score, 1);
    part.node = "Prong_3";
    EXPECT_EQ(stone_evidence(part, &m).score, -1);
    part.node = "Diamond_1";
    m.transmission = 1.0;
    EXPECT_EQ(stone_evidence(part, &m).score, 6);
}

TEST(MeshRepair, ATJunctionSliverGoesAndTheMeshStaysClosed) {
    // A tetrahedron whose edge 0–1 carries a corner 4 at its middle on one side only.
    const std::vector<glm::dvec3> p = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 0, 0}};
    MeshTriangles t = {{0, 2, 1}, {0, 4, 3}, {4, 1, 3}, {0, 1, 4}, {1, 2, 3}, {0, 3, 2}};
    // {0, 1, 4}: a sliver closing the T-junction against {0, 2, 1}, which runs 1 → 0.
    EXPECT_EQ(drop_zero_area_triangles(p, t), 1u);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& tri : t) {
        for (int k = 0; k < 3; ++k) ++edges[{tri[k], tri[(k + 1) % 3]}];
    }
    for (const auto& [e, n] : edges) {
        EXPECT_EQ(n, 1);
        EXPECT_TRUE(edges.contains({e.second, e.first})) << e.first << "→" << e.second;
    }
}

TEST(MeshRepair, FlippedTrianglesAreTurnedAndHolesFilled) {
    const std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    MeshTriangles t = {{0, 2, 1}, {0, 3, 1}, {1, 2, 3}};  // the second flipped; 0-3-2 missing
    auto turned = orient_consistently(t);
    ASSERT_TRUE(turned);
    EXPECT_EQ(turned.value(), 1u);
    auto filled = fill_holes(p, t);
    ASSERT_TRUE(filled) << filled.error();
    EXPECT_EQ(filled.value(), 1u);
    ASSERT_EQ(t.size(), 4u);
    // Closed and wound outward: its signed volume is the tetrahedron's 1/6.
    double volume6 = 0.0;
    for (const auto& tri : t) volume6 += glm::dot(p[tri[0]], glm::cross(p[tri[1]], p[tri[2]]));
    EXPECT_NEAR(std::abs(volume6), 1.0, 1e-12);
}

// A CAD shank of 225,280 triangles (a torus: 512 segments round, 220 about its section) is
// simplified asking for the chord tolerance: every corner left is one of the torus's own, and
// the torus's corners (every 127th, 888 of them) lie within 4 times the tolerance of the
// simplified surface (0.01 mm, a pixel at the kiosk's closest view; meshoptimizer's error is an
// estimate: 3.7 times is what it gives here), found by brute force over its triangles. The count
// it comes to and the farthest corner are printed.
TEST(MetalSimplify, ACadShankStaysWithinAPixelAtTheClosestView) {
    const MetalMesh full = cad::shank(9.0, 512, 220);
    MetalMesh simple = full;
    EXPECT_EQ(simplify_metal(simple, kChordToleranceMm), 225280u);
    std::printf("225,280 triangles simplified to %zu asking for %.4f mm\n", simple.triangle_count(),
                kChordToleranceMm);
    EXPECT_LT(simple.triangle_count(), full.triangle_count() / 4);
    ASSERT_GT(simple.triangle_count(), 0u);
    std::set<std::array<float, 3>> corners;
    for (const glm::vec3& q : full.positions) corners.insert({q.x, q.y, q.z});
    for (const glm::vec3& p : simple.positions) EXPECT_TRUE(corners.contains({p.x, p.y, p.z}));
    double worst = 0.0;
    for (std::size_t i = 0; i < full.positions.size(); i += 127) {
        const glm::dvec3 p(full.positions[i]);
        double nearest = HUGE_VAL;
        for (std::size_t t = 0; t + 2 < simple.indices.size(); t += 3) {
            const glm::dvec3 a(simple.positions[simple.indices[t]]);
            const glm::dvec3 b(simple.positions[simple.indices[t + 1]]);
            const glm::dvec3 c(simple.positions[simple.indices[t + 2]]);
            nearest = std::min(nearest, glm::length(p - closest_on_triangle(p, a, b, c)));
        }
        worst = std::max(worst, nearest);
    }
    std::printf("the farthest of the torus's corners is %.4f mm from the simplified surface\n",
                worst);
    EXPECT_LT(worst, 4.0 * kChordToleranceMm);
}

}  // namespace
}  // namespace gem
