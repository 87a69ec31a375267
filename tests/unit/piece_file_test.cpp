// Piece descriptions: the shipped samples load as the settings they name, and every kind of bad
// input gets one message naming the file, the line and the key (or the stones at fault).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "gemdb/sections.hpp"
#include "piece/piece_check.hpp"
#include "piece/piece_file.hpp"
#include "piece/stone_shape.hpp"
#include "scene/stone_file.hpp"

namespace gem {
namespace {

namespace fs = std::filesystem;

const fs::path kPieces = fs::path(GEM_CONFIG_DIR) / "pieces";
const fs::path kStones = fs::path(GEM_CONFIG_DIR) / "stones";

Result<Piece> parse(const std::string& text) {
    return parse_piece(text, "test.toml", kPieces);
}

std::string error_of(const std::string& text) {
    auto piece = parse(text);
    EXPECT_FALSE(piece) << "parsed: " << text;
    return piece ? std::string() : piece.error();
}

TEST(PieceFile, TheSamplesLoadAsTheirSettings) {
    auto solitaire = load_piece(kPieces / "solitaire.toml");
    ASSERT_TRUE(solitaire) << solitaire.error();
    EXPECT_EQ(solitaire.value().stones.size(), 1u);

    auto halo = load_piece(kPieces / "halo.toml");
    ASSERT_TRUE(halo) << halo.error();
    EXPECT_GE(halo.value().stones.size(), 21u);
    EXPECT_EQ(halo.value().kinds.size(), 2u);
    // The melee is scaled to the 1.3 mm the piece asks (the description says 1.3 too).
    EXPECT_NEAR(2.0 * stone_extent(halo.value().kinds[1]).girdle_radius, 1.3, 0.01);

    auto trilogy = load_piece(kPieces / "three-stone.toml");
    ASSERT_TRUE(trilogy) << trilogy.error();
    EXPECT_EQ(trilogy.value().stones.size(), 3u);
    // The 1.3 mm melee description scaled to 4 mm for the side stones.
    EXPECT_NEAR(2.0 * stone_extent(trilogy.value().kinds[1]).girdle_radius, 4.0, 0.05);

    auto band = load_piece(kPieces / "eternity-band.toml");
    ASSERT_TRUE(band) << band.error();
    EXPECT_GE(band.value().stones.size(), 30u);
    EXPECT_EQ(band.value().kinds.size(), 1u);
    EXPECT_EQ(describe(band.value())
                  .rfind("piece Diamond eternity band: " +
                             std::to_string(band.value().stones.size()) + " stones (1 distinct), ",
                         0),
              0u)
        << describe(band.value());
}

// Every sample's metal is a mesh a GPU and a glTF validator take: finite positions, unit
// normals. (A claw's wire of no length once normalised its axis into NaNs.)
TEST(PieceFile, EverySampleHasFiniteMetalAndPassesThePieceCheck) {
    for (const auto& entry : fs::directory_iterator(kPieces)) {
        if (entry.path().extension() != ".toml") continue;
        auto piece = load_piece(entry.path());
        ASSERT_TRUE(piece) << piece.error();
        const MetalMesh& metal = piece.value().metal;
        ASSERT_EQ(metal.positions.size(), metal.normals.size());
        std::size_t bad = 0;
        for (std::size_t i = 0; i < metal.positions.size(); ++i) {
            const glm::vec3 p = metal.positions[i];
            const float n = glm::length(metal.normals[i]);
            if (!std::isfinite(p.x + p.y + p.z) || !(std::abs(n - 1.0f) < 1e-4f)) ++bad;
        }
        EXPECT_EQ(bad, 0u) << entry.path().filename();
        // And every sample holds its stones as a free piece must (a heart's pointed culet was
        // once cut into by the straight wire between two of its basket's steps).
        auto held = check_piece(piece.value());
        EXPECT_TRUE(held) << entry.path().filename() << ": " << held.error();
    }
}

// Each kind of stone remembers its description and the width the piece sized it to, so that
// the same stone can be made again elsewhere (its tables: gemtables build --width-mm).
TEST(PieceFile, EachKindKnowsItsDescriptionAndWidth) {
    auto trilogy = load_piece(kPieces / "heart-trilogy.toml");
    ASSERT_TRUE(trilogy) << trilogy.error();
    const Piece& p = trilogy.value();
    ASSERT_EQ(p.kinds.size(), 2u);
    ASSERT_EQ(p.kind_sources.size(), 2u);
    EXPECT_EQ(p.kind_sources[0].description.filename(), "heart-ruby.toml");
    EXPECT_EQ(p.kind_sources[0].width_mm, 0.0);
    EXPECT_EQ(p.kind_sources[1].description.filename(), "melee-diamond.toml");
    EXPECT_EQ(p.kind_sources[1].width_mm, 3.5);
    EXPECT_FALSE(p.kinds[0].convex);  // the heart: its tables are worth building
    // Made again from its source, each kind is the piece's to the last bit.
    for (std::size_t k = 0; k < p.kinds.size(); ++k) {
        auto made = load_stone_file(p.kind_sources[k].description);
        ASSERT_TRUE(made) << made.error();
        Stone stone = std::move(made).value();
        if (p.kind_sources[k].width_mm > 0.0) {
            stone = stone_at_width(std::move(stone), p.kind_sources[k].width_mm);
        }
        EXPECT_TRUE(same_stored_stone(stone, p.kinds[k])) << k;
    }
    EXPECT_NEAR(girdle_width(p.kinds[1]), 3.5, 1e-9);
}

TEST(PieceFile, AMissingStoneFileIsNamedWithItsKey) {
    const std::string e = error_of(R"([piece]
name = "x"
setting = "solitaire"

[centre]
stone = "../stones/no-such-stone.toml"
)");
    EXPECT_EQ(e.rfind("test.toml:6: centre.stone: cannot read ", 0), 0u) << e;
    EXPECT_NE(e.find("no-such-stone.toml: no such file"), std::string::npos) << e;
}

TEST(PieceFile, ASettingParameterOutOfRangeIsNamedWithItsLine) {
    std::string e = error_of(R"([piece]
name = "x"
setting = "halo"

[centre]
stone = "../stones/tolkowsky-diamond.toml"

[small]
stone = "../stones/melee-diamond.toml"
gap_mm = 5.0
)");
    EXPECT_EQ(e, "test.toml:10: small.gap_mm: must be 0.05..2");
    e = error_of(R"([piece]
name = "x"
setting = "solitaire"
finger_diameter_mm = 40

[centre]
stone = "../stones/tolkowsky-diamond.toml"
)");
    EXPECT_EQ(e, "test.toml:4: piece.finger_diameter_mm: must be 10..30");
    e = error_of(R"([piece]
name = "x"
setting = "solitaire"

[centre]
stone = "../stones/tolkowsky-diamond.toml"
claws = 40
)");
    EXPECT_EQ(e, "test.toml:7: centre.claws: must be between 2 and 12");
}

TEST(PieceFile, UnknownKeysSettingsAndMetalsAreRefused) {
    EXPECT_EQ(error_of("[piece]\nname = \"x\"\nsetting = \"pendant\"\n"),
              "test.toml:3: piece.setting: unknown setting 'pendant' (solitaire, halo, "
              "three-stone, band, free)");
    EXPECT_EQ(error_of("[piece]\nname = \"x\"\nsetting = \"band\"\nmetal = \"rose_gold\"\n"),
              "test.toml:4: piece.metal: unknown metal 'rose_gold' (yellow_gold, white_gold, "
              "platinum, silver)");
    EXPECT_EQ(error_of("[piece]\nname = \"x\"\nsetting = \"band\"\ncolour = 3\n"),
              "test.toml:4: piece.colour: unknown key");
    EXPECT_EQ(error_of("[piece]\nname = \"x\"\nsetting = \"solitaire\"\n[centre]\n"
                       "stone = \"../stones/tolkowsky-diamond.toml\"\nbeads = 2\n"),
              "test.toml:6: centre.beads: unknown key");
    // Not TOML at all: the line and column.
    EXPECT_EQ(error_of("[piece\n").rfind("test.toml:1:", 0), 0u);
    // A halo without its small stones.
    EXPECT_EQ(error_of("[piece]\nname = \"x\"\nsetting = \"halo\"\n[centre]\n"
                       "stone = \"../stones/tolkowsky-diamond.toml\"\n"),
              "test.toml: small: a halo needs its small stones");
}

// A free piece: two 2 mm diamonds on a flat plate of metal whose top is at the culets' height.
class FreePiece : public ::testing::Test {
  protected:
    void SetUp() override {
        // A folder per test: ctest runs the tests of this fixture side by side, and one's
        // SetUp would rewrite the files another is reading.
        dir_ = fs::path(GEM_ARTIFACT_DIR) / "free_piece" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::create_directories(dir_);
        std::ofstream stone(dir_ / "small.toml");
        stone << "[stone]\ncut = \"round\"\nwidth_mm = 2.0\n[material]\nname = \"diamond\"\n";
        // The 2 mm Tolkowsky stone's culet is 0.86 mm below its girdle centre (43.1 % of its
        // width, from the pavilion angle: 1 mm × tan 40.75°).
        std::ofstream obj(dir_ / "plate.obj");
        const double top = -std::tan(40.75 * 3.14159265358979323846 / 180.0);
        obj << "v -5 " << top - 1 << " -5\nv 5 " << top - 1 << " -5\nv 5 " << top - 1 << " 5\nv -5 "
            << top - 1 << " 5\n"
            << "v -5 " << top << " -5\nv 5 " << top << " -5\nv 5 " << top << " 5\nv -5 " << top
            << " 5\n"
            << "f 1 2 3 4\nf 8 7 6 5\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n";
    }
    Result<Piece> free_piece(const std::string& second_position) {
        const std::string text =
            "[piece]\nname = \"free\"\nsetting = \"free\"\n"
            "metal_model = \"plate.obj\"\n"
            "[[stone]]\nstone = \"small.toml\"\n"
            "[[stone]]\nstone = \"small.toml\"\nrole = \"left\"\n"
            "position_mm = " +
            second_position + "\n";
        return parse_piece(text, "free.toml", dir_);
    }
    fs::path dir_;
};

TEST_F(FreePiece, StonesSeatedOnTheMetalApartFromEachOtherAreAPiece) {
    auto piece = free_piece("[-2.5, 0, 0]");
    ASSERT_TRUE(piece) << piece.error();
    EXPECT_EQ(piece.value().stones.size(), 2u);
    EXPECT_EQ(piece.value().kinds.size(), 1u);  // the same description at the same size
}

TEST_F(FreePiece, StonesThatIntersectAreNamed) {
    auto piece = free_piece("[-1.5, 0, 0]");
    ASSERT_FALSE(piece);
    EXPECT_EQ(piece.error(), "free.toml: stone 2 ('left') intersects stone 1 ('centre')");
}

TEST_F(FreePiece, AStoneFloatingOffItsSeatIsNamed) {
    auto piece = free_piece("[-2.5, 0.5, 0]");
    ASSERT_FALSE(piece);
    EXPECT_EQ(piece.error().rfind("free.toml: stone 2 ('left') floats off its seat", 0), 0u)
        << piece.error();
}

TEST_F(FreePiece, AStoneSunkIntoTheMetalIsNamed) {
    auto piece = free_piece("[-2.5, -0.3, 0]");
    ASSERT_FALSE(piece);
    EXPECT_NE(piece.error().find("cuts 0.3"), std::string::npos) << piece.error();
    EXPECT_NE(piece.error().find("stone 2 ('left')"), std::string::npos) << piece.error();
}

}  // namespace
}  // namespace gem
