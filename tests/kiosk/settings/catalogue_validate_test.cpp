// validate_catalogue: a good catalogue comes back with its databases open; every damaged file
// is refused in one line naming the catalogue, the file and the fault.

#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/cuts.hpp"
#include "optics/material.hpp"
#include "piece/gltf_piece_writer.hpp"
#include "piece/piece_file.hpp"

#include "catalogue/entry_models.hpp"
#include "catalogue/validate.hpp"
#include "catalogue_test_support.hpp"
#include "gemdb/reader.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using namespace catalogue_test;

// A tetrahedron under the stone, four faces written by hand: 12 triangle corners.
const char* kTetrahedronObj = R"(v 0 -5 -1
v 1 -5 1
v -1 -5 1
v 0 -4 0
f 1 2 3
f 1 4 2
f 2 4 3
f 3 4 1
)";

fs::path two_stone_catalogue(const std::string& name) {
    const fs::path dir = fresh_dir(name);
    write_text(dir / "catalogue.toml", R"([catalogue]
name = "spring"
[[stone]]
name = "Round"
database = "stones/round.gemdb"
[[stone]]
name = "Round in a ring"
database = "stones/second.gemdb"
ring = "rings/tetra.obj"
metal = "platinum"
)");
    write_bytes(dir / "stones" / "round.gemdb", read_bytes(tiny_database()));
    write_bytes(dir / "stones" / "second.gemdb", read_bytes(tiny_database()));
    write_text(dir / "rings" / "tetra.obj", kTetrahedronObj);
    return dir;
}

std::string rejection(const std::string& catalogue, const fs::path& dir) {
    auto result = validate_catalogue(dir);
    if (result.ok()) return "(accepted " + catalogue + ")";
    return result.error();
}

TEST(CatalogueValidate, GoodCatalogueComesBackOpen) {
    const fs::path dir = two_stone_catalogue("validate-good");
    auto result = validate_catalogue(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    EXPECT_EQ(c.name, "spring");
    EXPECT_EQ(c.directory, fs::canonical(dir));
    ASSERT_EQ(c.stones.size(), 2u);
    const auto bytes = read_bytes(tiny_database());
    for (const CatalogueStone& stone : c.stones) {
        ASSERT_NE(stone.opened, nullptr) << stone.name;
        EXPECT_EQ(stone.opened->view_count(), header_view_count(bytes));
        EXPECT_EQ(stone.opened->path().parent_path(), fs::canonical(dir) / "stones");
    }
    EXPECT_EQ(c.stones[0].ring_mesh, nullptr) << "a parametric ring is made by the renderer";
    // The OBJ ring was loaded to check it, and let go: the second entry is not shown first.
    EXPECT_EQ(c.stones[1].ring_mesh, nullptr);
    EXPECT_TRUE(lacks_models(c.stones[1]));
    CatalogueStone near = c.stones[1];
    ASSERT_TRUE(build_entry_models(near));
    ASSERT_NE(near.ring_mesh, nullptr);
    EXPECT_EQ(near.ring_mesh->indices.size(), 12u);
}

TEST(CatalogueValidate, ThroughASymlinkNamesTheRealDirectory) {
    const fs::path dir = two_stone_catalogue("validate-target");
    const fs::path link = fs::path(GEM_ARTIFACT_DIR) / "catalogue" / "validate-link";
    fs::remove(link);
    fs::create_directory_symlink(dir, link);
    auto result = validate_catalogue(link);
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(result.value().directory, fs::canonical(dir));
}

TEST(CatalogueValidate, FlippedPayloadByteNamesFileViewAndLevel) {
    const auto good = read_bytes(tiny_database());
    const std::uint32_t views = header_view_count(good);
    ASSERT_GE(views, 2u) << "the tiny database should hold several views";
    for (const std::uint32_t view : {0u, views - 1}) {
        const fs::path dir = two_stone_catalogue("validate-flip-" + std::to_string(view));
        std::vector<std::uint8_t> bad = good;
        const PayloadSpan span = payload_span(bad, view, 0, 1);
        ASSERT_GT(span.bytes, 0u);
        bad.at(span.offset + span.bytes / 2) ^= 0x20;
        write_bytes(dir / "stones" / "second.gemdb", bad);
        // Opening checks only the header, sections and index: the payload check is what
        // must catch this.
        ASSERT_TRUE(Database::open(dir / "stones" / "second.gemdb").ok());
        EXPECT_EQ(rejection("flip", dir),
                  "catalogue 'spring' rejected: stones/second.gemdb: view " + std::to_string(view) +
                      " level 0: checksum mismatch");
    }
}

TEST(CatalogueValidate, TruncatedDatabaseIsNamed) {
    const fs::path dir = two_stone_catalogue("validate-truncated");
    auto bytes = read_bytes(tiny_database());
    const std::size_t full = bytes.size();
    bytes.resize(full / 2);
    write_bytes(dir / "stones" / "round.gemdb", bytes);
    EXPECT_EQ(rejection("truncated", dir),
              "catalogue 'spring' rejected: stones/round.gemdb: truncated: " +
                  std::to_string(full / 2) + " of " + std::to_string(full) + " bytes");
}

TEST(CatalogueValidate, MissingDatabaseIsNamed) {
    const fs::path dir = two_stone_catalogue("validate-missing");
    fs::remove(dir / "stones" / "second.gemdb");
    EXPECT_EQ(rejection("missing", dir),
              "catalogue 'spring' rejected: stones/second.gemdb: "
              "cannot open: No such file or directory");
}

TEST(CatalogueValidate, BrokenRingNamesFileAndLine) {
    const fs::path dir = two_stone_catalogue("validate-ring");
    write_text(dir / "rings" / "tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 9\n");
    EXPECT_EQ(rejection("ring", dir),
              "catalogue 'spring' rejected: rings/tetra.obj:5: face "
              "index 9 out of range (4 vertices so far)");
}

// Opened for its first stone only (the kiosk's start), a catalogue is not read past it: a later
// database that is damaged is not seen, and what is not checked is counted. Whole, it is refused.
TEST(CatalogueValidate, OpenedForItsFirstStoneItReadsNothingAfterIt) {
    const fs::path dir = two_stone_catalogue("validate-first");
    auto bytes = read_bytes(tiny_database());
    bytes.resize(bytes.size() / 2);
    write_bytes(dir / "stones" / "second.gemdb", bytes);
    write_text(dir / "rings" / "tetra.obj", "f 1 2 9\n");
    auto first = validate_catalogue(dir, {}, {}, DigestCheck::check, Entries::first);
    ASSERT_TRUE(first.ok()) << first.error();
    ASSERT_EQ(first.value().stones.size(), 1u);
    EXPECT_EQ(first.value().stones[0].name, "Round");
    ASSERT_NE(first.value().stones[0].opened, nullptr);
    EXPECT_EQ(first.value().unchecked, 1u);
    EXPECT_NE(rejection("whole", dir).find("stones/second.gemdb: truncated"), std::string::npos);
}

// A first entry that cannot be shown is left out as usual, and the next one is the first.
TEST(CatalogueValidate, OpenedForItsFirstStoneALeftOutEntryIsPassed) {
    const fs::path dir = fresh_dir("validate-first-design");
    write_text(dir / "catalogue.toml", R"([catalogue]
name = "designs"
[[stone]]
name = "Odd"
design = "odd.toml"
[[stone]]
name = "Round"
design = "round.toml"
[[stone]]
name = "Round again"
design = "round.toml"
[[stone]]
name = "Odd again"
design = "odd.toml"
)");
    write_text(dir / "round.toml", "[stone]\ncut = \"round\"\n[material]\nname = \"diamond\"\n");
    write_text(dir / "odd.toml", "[stone]\ncut = \"dodecahedron\"\n");
    auto first = validate_catalogue(dir, {}, {}, DigestCheck::check, Entries::first);
    ASSERT_TRUE(first.ok()) << first.error();
    const Catalogue& c = first.value();
    ASSERT_EQ(c.stones.size(), 1u);
    EXPECT_EQ(c.stones[0].name, "Round");
    EXPECT_EQ(c.unchecked, 2u);
    ASSERT_EQ(c.left_out.size(), 1u);
    EXPECT_EQ(c.left_out[0].rfind("stone 'Odd' left out", 0), 0u) << c.left_out[0];
    auto whole = validate_catalogue(dir);
    ASSERT_TRUE(whole.ok()) << whole.error();
    EXPECT_EQ(whole.value().stones.size(), 2u);
    EXPECT_EQ(whole.value().left_out.size(), 2u);
    EXPECT_EQ(whole.value().unchecked, 0u);
}

TEST(CatalogueValidate, ManifestFaultNamesTheDirectory) {
    const fs::path dir = two_stone_catalogue("validate-manifest");
    write_text(dir / "catalogue.toml", "[catalogue]\nname = \"spring\"\n");
    EXPECT_EQ(rejection("manifest", dir),
              "catalogue 'validate-manifest' rejected: "
              "catalogue.toml:1: stone: no [[stone]] entries");
}

TEST(CatalogueValidate, MissingDirectoryIsNamed) {
    const fs::path dir = fresh_dir("validate-gone") / "nothing";
    const std::string error = rejection("gone", dir);
    EXPECT_EQ(error.rfind("catalogue 'nothing' rejected: " + dir.string() + ": ", 0), 0u) << error;
}

TEST(CatalogueValidate, DesignsAreBuiltAndABrokenOneIsLeftOutByName) {
    const fs::path dir = fresh_dir("validate-designs");
    write_text(dir / "catalogue.toml", R"([catalogue]
name = "designs"
[[stone]]
name = "Round"
design = "round.toml"
[[stone]]
name = "Odd"
design = "odd.toml"
)");
    write_text(dir / "round.toml", "[stone]\ncut = \"round\"\n[material]\nname = \"diamond\"\n");
    write_text(dir / "odd.toml", "[stone]\ncut = \"dodecahedron\"\n");
    auto result = validate_catalogue(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    ASSERT_EQ(c.stones.size(), 1u);
    EXPECT_EQ(c.stones[0].name, "Round");
    ASSERT_NE(c.stones[0].designed, nullptr);
    EXPECT_EQ(c.stones[0].opened, nullptr);
    EXPECT_EQ(c.stones[0].designed->material.name, "diamond");
    // The default round, as the cut generator makes it directly.
    const Stone direct =
        make_cut(default_cut_params(CutShape::round_brilliant), *find_material("diamond")).value();
    EXPECT_EQ(c.stones[0].designed->facets.size(), direct.facets.size());
    EXPECT_EQ(c.stones[0].designed->vertices.size(), direct.vertices.size());
    ASSERT_EQ(c.left_out.size(), 1u);
    EXPECT_EQ(c.left_out[0].rfind("stone 'Odd' left out: odd.toml:2: ", 0), 0u) << c.left_out[0];

    // With no design readable there is nothing to show: the catalogue is refused.
    write_text(dir / "round.toml", "[stone]\ncut = \"dodecahedron\"\n");
    EXPECT_NE(rejection("designs", dir).find("rejected: stone 'Round' left out"), std::string::npos)
        << rejection("designs", dir);
}

// A piece is read with its stones and checked as gemrender reads it; a piece that names a
// missing stone file, or whose setting parameter is out of range, is left out in one line naming
// the piece, its file, the line and the key, and the catalogue's other entries show.
TEST(CatalogueValidate, PiecesAreReadAndABrokenOneIsLeftOutByName) {
    const fs::path dir = fresh_dir("validate-pieces");
    write_text(dir / "catalogue.toml", R"([catalogue]
name = "pieces"
[[stone]]
name = "Halo"
piece = "pieces/halo.toml"
[[stone]]
name = "No stone"
piece = "pieces/missing-stone.toml"
[[stone]]
name = "Wide gap"
piece = "pieces/wide-gap.toml"
)");
    const std::string halo = copy_shipped_halo(dir);
    std::string missing = halo;
    missing.replace(missing.find("melee-diamond"), 13, "pebble");
    write_text(dir / "pieces" / "missing-stone.toml", missing);
    std::string wide = halo;
    wide.replace(wide.find("gap_mm = 0.15"), 13, "gap_mm = 9.00");
    write_text(dir / "pieces" / "wide-gap.toml", wide);

    auto result = validate_catalogue(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    ASSERT_EQ(c.stones.size(), 1u);
    EXPECT_EQ(c.stones[0].name, "Halo");
    ASSERT_NE(c.stones[0].placed, nullptr);
    // The shipped halo: the centre stone and 22 small ones (config/pieces/halo.toml).
    EXPECT_EQ(c.stones[0].placed->stones.size(), 23u);
    EXPECT_EQ(c.stones[0].placed->kinds.size(), 2u);
    ASSERT_EQ(c.left_out.size(), 2u);
    EXPECT_EQ(c.left_out[0].rfind("piece 'No stone' left out: pieces/missing-stone.toml:", 0), 0u)
        << c.left_out[0];
    EXPECT_NE(c.left_out[0].find("small.stone"), std::string::npos) << c.left_out[0];
    EXPECT_NE(c.left_out[0].find("pebble.toml"), std::string::npos) << c.left_out[0];
    EXPECT_EQ(c.left_out[1].rfind("piece 'Wide gap' left out: pieces/wide-gap.toml:", 0), 0u)
        << c.left_out[1];
    EXPECT_NE(c.left_out[1].find("small.gap_mm: must be"), std::string::npos) << c.left_out[1];
}

// A piece from CAD as glTF (.glb): read and checked when the catalogue arrives, with one note a
// kind of stone saying how it was recognised. A convex gem that is not closed (an export lost a
// triangle) is closed by the planes of its facets, said in its note; a truncated .glb, and a
// heart (not convex) that is not closed, are left out in one line each naming the file and the
// fault (the node, for the gem).
TEST(CatalogueValidate, GltfPiecesAreReadAndABrokenOneIsLeftOutByName) {
    const fs::path dir = fresh_dir("validate-gltf");
    write_text(dir / "catalogue.toml", R"([catalogue]
name = "cad"
[[stone]]
name = "Halo"
piece = "pieces/halo.glb"
[[stone]]
name = "Cut short"
piece = "pieces/truncated.glb"
[[stone]]
name = "Open halo"
piece = "pieces/open-halo.glb"
[[stone]]
name = "Open heart"
piece = "pieces/open-heart.glb"
)");
    const fs::path pieces = fs::path(GEM_SOURCE_DIR) / "config" / "pieces";
    auto halo = load_piece(pieces / "halo.toml");
    ASSERT_TRUE(halo) << halo.error();
    auto hearts = load_piece(pieces / "heart-trilogy.toml");
    ASSERT_TRUE(hearts) << hearts.error();
    fs::create_directories(dir / "pieces");
    ASSERT_TRUE(write_piece_glb(halo.value(), dir / "pieces" / "halo.glb"));
    const std::vector<std::uint8_t> bytes = read_bytes(dir / "pieces" / "halo.glb");
    write_text(dir / "pieces" / "truncated.glb",
               std::string(bytes.begin(), bytes.begin() + bytes.size() / 3));
    // Each written with a triangle of its centre stone missing.
    Piece open = halo.value();
    open.kinds[0].triangles.pop_back();
    ASSERT_TRUE(write_piece_glb(open, dir / "pieces" / "open-halo.glb"));
    Piece open_heart = hearts.value();
    ASSERT_FALSE(open_heart.kinds[0].convex);
    open_heart.kinds[0].triangles.pop_back();
    ASSERT_TRUE(write_piece_glb(open_heart, dir / "pieces" / "open-heart.glb"));

    auto result = validate_catalogue(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    ASSERT_EQ(c.stones.size(), 3u);
    EXPECT_EQ(c.stones[0].name, "Halo");
    EXPECT_EQ(c.stones[1].name, "Open halo");
    EXPECT_EQ(c.stones[2].name, "Open heart");
    // Only the entry shown first holds its piece; the others are built as they come near,
    // from the same files, to the same pieces.
    ASSERT_NE(c.stones[0].placed, nullptr);
    std::vector<CatalogueStone> near = c.stones;
    for (std::size_t i = 1; i < near.size(); ++i) {
        EXPECT_EQ(near[i].placed, nullptr) << near[i].name;
        ASSERT_TRUE(build_entry_models(near[i]));
    }
    for (std::size_t i = 0; i < 2; ++i) {
        const CatalogueStone& stone = near[i];
        ASSERT_NE(stone.placed, nullptr);
        EXPECT_EQ(stone.placed->stones.size(), 23u);
        ASSERT_EQ(stone.placed->kinds.size(), 2u);
        // The closed centre has every facet of the cut, convex.
        EXPECT_EQ(stone.placed->kinds[0].facets.size(), halo.value().kinds[0].facets.size());
        EXPECT_TRUE(stone.placed->kinds[0].convex);
    }
    // The open heart, not convex, has its hole filled: every facet of the cut again.
    ASSERT_NE(near[2].placed, nullptr);
    EXPECT_EQ(near[2].placed->kinds[0].facets.size(), hearts.value().kinds[0].facets.size());
    EXPECT_FALSE(near[2].placed->kinds[0].convex);
    const auto said = [&](const std::vector<std::string>& lines, const std::string& piece,
                          const std::string& text) {
        return std::any_of(lines.begin(), lines.end(), [&](const std::string& n) {
            return n.rfind("piece '" + piece + "': ", 0) == 0 && n.find(text) != std::string::npos;
        });
    };
    EXPECT_TRUE(said(c.notes, "Halo", "stone node 'centre'"));
    EXPECT_TRUE(said(c.notes, "Halo", "transmissive"));
    EXPECT_EQ(c.warnings.size(), 2u);
    EXPECT_TRUE(said(c.warnings, "Open halo",
                     "open-halo.glb: node 'centre' (mesh 'gem 1 round-brilliant'): repaired; "
                     "open (3 boundary edges): closed by the planes of its facets"));
    EXPECT_TRUE(said(c.warnings, "Open heart",
                     "open-heart.glb: node 'centre' (mesh 'gem 1 heart'): repaired; open (3 "
                     "boundary edges): 1 hole filled"));
    ASSERT_EQ(c.left_out.size(), 1u);
    EXPECT_EQ(c.left_out[0].rfind("piece 'Cut short' left out: pieces/truncated.glb: ", 0), 0u)
        << c.left_out[0];
}

}  // namespace
}  // namespace gem::kiosk
