// A shop's catalogue of pieces: a kiosk started on a catalogue whose first entry is the shipped
// halo ring shows it, framed at the start view, its small stones given their own model (one log
// line for the distinct stone); a piece whose stone file is missing is left out with one line
// naming the piece, its file, the line and the key. Checked on the real program's log and a
// snapshot against a reference drawn in this process.
#include <signal.h>

#include <gtest/gtest.h>

#include <fstream>

#include "e2e_fixture.hpp"
#include "kiosk_process.hpp"

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

}  // namespace
}  // namespace gem::kiosk_e2e
