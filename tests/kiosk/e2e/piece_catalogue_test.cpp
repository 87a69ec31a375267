// A shop's catalogue of pieces: a kiosk started on a catalogue whose first entry is the shipped
// halo ring shows it, framed at the start view, its small stones given their own model (one log
// line for the distinct stone); a piece whose stone file is missing is left out with one line
// naming the piece, its file, the line and the key. Checked on the real program's log and a
// snapshot against a reference drawn in this process.
#include <signal.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <numbers>

#include "e2e_fixture.hpp"
#include "kiosk_process.hpp"
#include "stage/start_view.hpp"

namespace gem::kiosk_e2e {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// The halo and a copy of it whose small stones' file does not exist, with the stone files they
// name beside them as in config/.
fs::path piece_catalogue(const fs::path& dir) {
    const fs::path config = fs::path(GEM_SOURCE_DIR) / "config";
    fs::create_directories(dir / "pieces");
    fs::create_directories(dir / "stones");
    for (const char* stone : {"tolkowsky-diamond.toml", "melee-diamond.toml"}) {
        fs::copy_file(config / "stones" / stone, dir / "stones" / stone);
    }
    fs::copy_file(config / "pieces" / "halo.toml", dir / "pieces" / "halo.toml");
    std::ifstream in(config / "pieces" / "halo.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("melee-diamond"), 13, "pebble");
    std::ofstream(dir / "pieces" / "pebbles.toml") << text;
    std::ofstream(dir / "catalogue.toml") << "[catalogue]\nname = \"pieces\"\n\n"
                                          << "[[stone]]\nname = \"halo\"\n"
                                          << "piece = \"pieces/halo.toml\"\n\n"
                                          << "[[stone]]\nname = \"pebbles\"\n"
                                          << "piece = \"pieces/pebbles.toml\"\n";
    return dir;
}

TEST(KioskPieces, APieceIsShownAndABrokenOneIsLeftOut) {
    auto sapphire = test_catalogue("oval-sapphire");
    ASSERT_TRUE(sapphire.ok()) << sapphire.error();
    const fs::path dir = fresh_dir("piece-catalogue");
    const fs::path pieces = piece_catalogue(dir / "pieces");
    const fs::path config = write_config(dir, pieces);
    KioskProcess kiosk({GEMKIOSK_PATH, "--config", config.string(), "--seconds", "150"});
    ASSERT_TRUE(kiosk.wait_for_line("first frame on screen", 90s)) << kiosk.log();
    // The entries after the first are checked in the background (CatalogueCompletion), which
    // may end before the first frame is on screen or after it.
    const std::string checked = "every entry checked, 1 to show, 1 left out";
    ASSERT_TRUE(kiosk.log().find(checked) != std::string::npos || kiosk.wait_for_line(checked, 90s))
        << kiosk.log();
    const std::string log = kiosk.log();
    // One error line names the piece, its file, the key and the missing file.
    const auto at = log.find("piece 'pebbles' left out: pieces/pebbles.toml:");
    ASSERT_NE(at, std::string::npos) << log;
    const auto line_start = log.rfind('\n', at) + 1;
    EXPECT_EQ(log.rfind("<3>", line_start), line_start) << log.substr(line_start, 200);
    const std::string line = log.substr(at, log.find('\n', at) - at);
    EXPECT_NE(line.find("small.stone"), std::string::npos) << line;
    EXPECT_NE(line.find("pebble.toml"), std::string::npos) << line;
    // The halo's small diamonds measured once, as one distinct stone.
    EXPECT_NE(log.find("stone model: 1.3 mm diamond (x22)"), std::string::npos) << log;

    const Image shown = settled_snapshot(kiosk, dir / "snapshots" / "snapshot.png");
    ASSERT_FALSE(shown.pixels.empty()) << kiosk.log();
    expect_shows(shown, pieces, sapphire.value(), "the halo ring");

    kiosk.signal(SIGTERM);
    EXPECT_EQ(kiosk.wait(30s), 0) << kiosk.log();
}

// A piece whose side stones are hearts (not convex: the trace tests each of their triangles per
// bounce): their tables are built in the background, sized as the piece sizes them and storing
// every direction, and the piece is then drawn with them, its convex centre still traced. The
// snapshot is checked against the piece drawn in this process from the very tables the kiosk
// built.
TEST(KioskPieces, ItsNonConvexStonesAreDrawnFromTablesBuiltForThem) {
    auto sapphire = test_catalogue("oval-sapphire");
    ASSERT_TRUE(sapphire.ok()) << sapphire.error();
    const fs::path dir = fresh_dir("piece-tables");
    const fs::path pieces = dir / "pieces";
    const fs::path config_dir = fs::path(GEM_SOURCE_DIR) / "config";
    fs::create_directories(pieces / "stones");
    for (const char* stone : {"oval-sapphire.toml", "heart-ruby.toml"}) {
        fs::copy_file(config_dir / "stones" / stone, pieces / "stones" / stone);
    }
    std::ofstream(pieces / "trio.toml")
        << "[piece]\nname = \"Heart trio\"\nsetting = \"three-stone\"\nmetal = \"white_gold\"\n\n"
        << "[centre]\nstone = \"stones/oval-sapphire.toml\"\n\n"
        << "[small]\nstone = \"stones/heart-ruby.toml\"\nwidth_mm = 4.0\n";
    std::ofstream(pieces / "catalogue.toml") << "[catalogue]\nname = \"trio\"\n\n"
                                             << "[[stone]]\nname = \"trio\"\n"
                                             << "piece = \"trio.toml\"\n";
    // Tiny tables (32 and 64 px, every 20°, depth 4): a build of a few seconds.
    const fs::path config =
        write_config(dir, pieces,
                     "[designs]\ntables = \"always\"\nbuilder = \"" GEMTABLES_PATH
                     "\"\nlevel_px = 64\nspacing_deg = 20.0\ndepth = 4\n");
    KioskProcess kiosk({GEMKIOSK_PATH, "--config", config.string(), "--seconds", "150"});
    ASSERT_TRUE(kiosk.wait_for_line("first frame on screen", 90s)) << kiosk.log();
    const std::string in_use = "piece 'trio': its 4.0 mm stone 'heart': drawn from its tables, ";
    ASSERT_TRUE(kiosk.wait_for_line(in_use, 120s)) << kiosk.log();
    const std::string log = kiosk.log();
    const auto at = log.find(in_use) + in_use.size();
    const fs::path built = log.substr(at, log.find('\n', at) - at);
    ASSERT_TRUE(fs::exists(built)) << built;
    auto database = Database::open(built);
    ASSERT_TRUE(database) << database.error();
    EXPECT_EQ(database.value().params().grid.min_elevation_rad, -std::numbers::pi / 2.0);
    const std::vector<std::shared_ptr<const Database>> kind_tables = {
        nullptr, std::make_shared<const Database>(std::move(database).value())};

    const Image shown = settled_snapshot(kiosk, dir / "snapshots" / "snapshot.png");
    ASSERT_FALSE(shown.pixels.empty()) << kiosk.log();
    expect_shows(shown, pieces, sapphire.value(), "the trio with its hearts from tables",
                 kind_tables);
    // And not the piece with its hearts traced: the tiny tables show another picture of them.
    auto traced = reference_picture(pieces, kiosk::kStartView);
    ASSERT_TRUE(traced) << traced.error();
    const double traced_db = psnr_srgb8(shown, traced.value());
    std::printf("the same piece with its hearts traced: %.1f dB\n", traced_db);
    EXPECT_LT(traced_db, 50.0);
    if (std::getenv("GEM_KEEP_LOG") != nullptr) std::printf("%s\n", kiosk.log().c_str());
    kiosk.signal(SIGTERM);
    EXPECT_EQ(kiosk.wait(30s), 0) << kiosk.log();
}

}  // namespace
}  // namespace gem::kiosk_e2e
