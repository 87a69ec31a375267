// Staff deliver catalogues to a running kiosk: a valid one dropped into the inbox replaces the
// one on screen without the kiosk stopping; a damaged one is refused with a line naming the
// file, and the screen keeps what it had. Checked on the real program's log and snapshots.
#include <signal.h>

#include <gtest/gtest.h>

#include <fstream>

#include "e2e_fixture.hpp"
#include "kiosk_process.hpp"

namespace gem::kiosk_e2e {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// Flips one byte in the middle of a database: inside a view's compressed payload, which only
// the per-view checksums can catch.
void damage(const fs::path& database) {
    std::fstream f(database, std::ios::in | std::ios::out | std::ios::binary);
    const auto size = static_cast<std::streamoff>(fs::file_size(database));
    f.seekg(size / 2);
    char byte = 0;
    f.read(&byte, 1);
    byte = static_cast<char>(byte ^ 0x5a);
    f.seekp(size / 2);
    f.write(&byte, 1);
}

TEST(KioskCatalogue, NewCatalogueIsShownAndADamagedOneIsRefused) {
    auto sapphire = test_catalogue("oval-sapphire");
    auto diamond = test_catalogue("tolkowsky-diamond");
    ASSERT_TRUE(sapphire.ok() && diamond.ok());
    const fs::path dir = fresh_dir("catalogue-switch");
    const fs::path config = write_config(dir, sapphire.value());
    fs::create_directories(dir / "state" / "inbox");
    KioskProcess kiosk({GEMKIOSK_PATH, "--config", config.string(), "--seconds", "150"});
    ASSERT_TRUE(kiosk.wait_for_line("first frame on screen", 60s)) << kiosk.log();

    // Staff copy the diamond catalogue in; the kiosk validates, installs and shows it.
    fs::copy(diamond.value(), dir / "state" / "inbox" / "spring", fs::copy_options::recursive);
    ASSERT_TRUE(kiosk.wait_for_line("showing catalogue 'tolkowsky-diamond'", 60s)) << kiosk.log();
    const Image diamond_shown = snapshot_after_signal(kiosk, dir / "snapshots" / "snapshot.png");
    ASSERT_FALSE(diamond_shown.pixels.empty()) << kiosk.log();

    // Then a copy of it with one byte flipped inside a view.
    const fs::path bad = dir / "bad-copy";
    fs::copy(diamond.value(), bad, fs::copy_options::recursive);
    damage(bad / "tolkowsky-diamond.gemdb");
    fs::rename(bad, dir / "state" / "inbox" / "summer");
    ASSERT_TRUE(kiosk.wait_for_line("rejected", 60s)) << kiosk.log();
    // One line names the catalogue's database and the fault.
    const std::string log = kiosk.log();
    const auto line_start = log.rfind('\n', log.find("rejected")) + 1;
    const std::string line = log.substr(line_start, log.find('\n', line_start) - line_start);
    EXPECT_NE(line.find("tolkowsky-diamond.gemdb"), std::string::npos) << line;
    EXPECT_NE(line.find("checksum"), std::string::npos) << line;
    EXPECT_EQ(line.rfind("<3>", 0), 0u) << "an error line for journald: " << line;

    // The screen still shows the diamond, not the sapphire it started with.
    const Image after = settled_snapshot(kiosk, dir / "snapshots" / "snapshot.png");
    ASSERT_FALSE(after.pixels.empty()) << kiosk.log();
    expect_shows(after, diamond.value(), sapphire.value(), "after the damaged catalogue");

    kiosk.signal(SIGTERM);
    EXPECT_EQ(kiosk.wait(30s), 0) << kiosk.log();
    EXPECT_NE(kiosk.log().find("stopping on SIGTERM"), std::string::npos);
}

}  // namespace
}  // namespace gem::kiosk_e2e
