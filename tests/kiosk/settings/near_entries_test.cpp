// NearEntries: the entry going on screen gets its models built again from its files, the same
// as validation built them; the next one built ahead is the one handed over; an entry whose
// file went away since validation is an error naming the entry and the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "../../support/cad_corpus.hpp"
#include "catalogue/entry_models.hpp"
#include "catalogue/near_entries.hpp"
#include "catalogue/validate.hpp"
#include "catalogue_test_support.hpp"
#include "piece/gltf_piece.hpp"
#include "piece/piece_file.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using namespace catalogue_test;

// Three entries: the shipped halo as a piece, and two designs (the second a heart).
fs::path three_entry_catalogue(const std::string& name) {
    const fs::path dir = fresh_dir(name);
    copy_shipped_halo(dir);
    write_text(dir / "stones" / "heart.toml",
               "[stone]\ncut = \"heart\"\n[material]\nname = \"ruby\"\n");
    write_text(dir / "catalogue.toml", R"([catalogue]
name = "near"
[[stone]]
name = "Round"
design = "stones/tolkowsky-diamond.toml"
[[stone]]
name = "Halo"
piece = "pieces/halo.toml"
[[stone]]
name = "Heart"
design = "stones/heart.toml"
)");
    return dir;
}

TEST(NearEntries, ValidationKeepsTheFirstEntrysModelsOnlyAndTheOthersAreBuiltAlike) {
    const fs::path dir = three_entry_catalogue("near-built");
    auto result = validate_catalogue(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    ASSERT_EQ(c.stones.size(), 3u);
    EXPECT_FALSE(lacks_models(c.stones[0]));
    EXPECT_TRUE(lacks_models(c.stones[1]));
    EXPECT_TRUE(lacks_models(c.stones[2]));

    NearEntries near;
    // An entry holding its models comes back as it is: the very same objects.
    auto first = near.bring(c.stones[0]);
    ASSERT_TRUE(first) << first.error();
    EXPECT_EQ(first.value().designed, c.stones[0].designed);
    // Built now, and built ahead: each the piece the file gives when read directly.
    auto direct = load_piece(dir / "pieces" / "halo.toml");
    ASSERT_TRUE(direct) << direct.error();
    auto halo = near.bring(c.stones[1]);
    ASSERT_TRUE(halo) << halo.error();
    ASSERT_NE(halo.value().placed, nullptr);
    EXPECT_EQ(halo.value().placed->stones.size(), direct.value().stones.size());
    EXPECT_EQ(halo.value().placed->metal.indices, direct.value().metal.indices);
    near.build_ahead(c.stones[2]);
    auto heart = near.bring(c.stones[2]);
    ASSERT_TRUE(heart) << heart.error();
    ASSERT_NE(heart.value().designed, nullptr);
    EXPECT_FALSE(heart.value().designed->convex);
    EXPECT_EQ(heart.value().name, "Heart");
}

// Built ahead for one entry, then another brought: the one ahead is dropped, not handed over.
TEST(NearEntries, AnotherEntryThanTheOneBuiltAheadIsBuiltForItself) {
    const fs::path dir = three_entry_catalogue("near-other");
    auto result = validate_catalogue(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    NearEntries near;
    near.build_ahead(c.stones[1]);
    auto heart = near.bring(c.stones[2]);
    ASSERT_TRUE(heart) << heart.error();
    EXPECT_EQ(heart.value().name, "Heart");
    EXPECT_EQ(heart.value().placed, nullptr);
    ASSERT_NE(heart.value().designed, nullptr);
    auto halo = near.bring(c.stones[1]);
    ASSERT_TRUE(halo) << halo.error();
    EXPECT_NE(halo.value().placed, nullptr);
}

TEST(NearEntries, AFileGoneSinceValidationIsAnErrorNamingTheEntryAndTheFile) {
    const fs::path dir = three_entry_catalogue("near-gone");
    auto result = validate_catalogue(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    fs::remove(dir / "pieces" / "halo.toml");
    for (const bool ahead : {false, true}) {
        NearEntries near;
        if (ahead) near.build_ahead(c.stones[1]);
        auto halo = near.bring(c.stones[1]);
        ASSERT_FALSE(halo);
        EXPECT_EQ(halo.error().rfind("catalogue entry 'Halo': ", 0), 0u) << halo.error();
        EXPECT_NE(halo.error().find("halo.toml"), std::string::npos) << halo.error();
    }
}

// Files made as other tools make them (support/cad_corpus.hpp: CAD meshes split at their creases,
// metres, node trees, designers' names), each an entry after the first: what validation kept is
// built again near the screen to the piece the file gives when read directly, and what the
// reader said of the files (how it found their stones, what it repaired) was said once, at
// validation.
TEST(NearEntries, PiecesFromOtherToolsAreBuiltAgainAsTheFileReadsDirectly) {
    const fs::path dir = three_entry_catalogue("near-cad");
    const std::vector<test_support::cad::CorpusFile> corpus =
        test_support::cad::write_corpus(dir / "cad");
    std::string manifest = read_text(dir / "catalogue.toml");
    for (const auto& file : corpus) {
        manifest += "[[stone]]\nname = \"" + file.name + "\"\npiece = \"cad/" + file.name + "\"\n";
    }
    write_text(dir / "catalogue.toml", manifest);
    auto result = validate_catalogue(dir);
    ASSERT_TRUE(result.ok()) << result.error();
    const Catalogue& c = result.value();
    ASSERT_GT(c.stones.size(), 3u + corpus.size() / 2) << "most of the corpus is shown";
    int built = 0;
    NearEntries near;
    for (std::size_t i = 3; i < c.stones.size(); ++i) {
        const CatalogueStone& entry = c.stones[i];
        EXPECT_TRUE(lacks_models(entry)) << entry.name;
        if (i + 1 < c.stones.size()) near.build_ahead(c.stones[i + 1]);
        std::vector<std::string> said;
        auto direct = load_piece(entry.piece, &said);
        ASSERT_TRUE(direct) << entry.name << ": " << direct.error();
        testing::internal::CaptureStderr();
        auto brought = near.bring(entry);
        EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << entry.name;
        ASSERT_TRUE(brought) << brought.error();
        const Piece& piece = *brought.value().placed;
        EXPECT_EQ(piece.stones.size(), direct.value().stones.size()) << entry.name;
        EXPECT_EQ(piece.kinds.size(), direct.value().kinds.size()) << entry.name;
        EXPECT_EQ(piece.metal.indices, direct.value().metal.indices) << entry.name;
        EXPECT_EQ(piece.metal.positions.size(), direct.value().metal.positions.size())
            << entry.name;
        // Each line the reader says of the file is in what validation said, once.
        for (const std::string& line : said) {
            const bool warning = line.starts_with(kWarningLine);
            const std::string expected = "piece '" + entry.name + "': " +
                                         (warning ? line.substr(kWarningLine.size()) : line);
            const std::vector<std::string>& lines = warning ? c.warnings : c.notes;
            EXPECT_EQ(std::count(lines.begin(), lines.end(), expected), 1) << expected;
        }
        ++built;
    }
    EXPECT_EQ(built, static_cast<int>(c.stones.size()) - 3);
}

}  // namespace
}  // namespace gem::kiosk
