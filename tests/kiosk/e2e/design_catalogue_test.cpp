// Staff bring a design, not a database: a catalogue whose stones are stone descriptions
// (config/stones/*.toml) is dropped into a running kiosk's inbox and its stone is shown at
// once, drawn by the exact trace; a design that cannot be read is left out with one line
// naming it, and the catalogue's other stones show. Checked on the real program's log and a
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

// A catalogue of designs only: the emerald cut from config/stones, and a broken description.
fs::path design_catalogue(const fs::path& dir) {
    fs::create_directories(dir);
    fs::copy_file(fs::path(GEM_SOURCE_DIR) / "config/stones/emerald-cut-emerald.toml",
                  dir / "emerald.toml");
    std::ofstream(dir / "broken.toml") << "[stone]\ncut = \"round\"\nwidth_mm = -3.0\n";
    std::ofstream(dir / "catalogue.toml") << "[catalogue]\nname = \"designs\"\n\n"
                                          << "[[stone]]\nname = \"emerald\"\n"
                                          << "design = \"emerald.toml\"\n\n"
                                          << "[[stone]]\nname = \"broken\"\n"
                                          << "design = \"broken.toml\"\n";
    return dir;
}

TEST(KioskDesigns, ADesignIsShownAtOnceAndABrokenOneIsLeftOut) {
    auto sapphire = test_catalogue("oval-sapphire");
    ASSERT_TRUE(sapphire.ok()) << sapphire.error();
    const fs::path dir = fresh_dir("design-catalogue");
    const fs::path designs = design_catalogue(dir / "delivery");
    const fs::path config = write_config(dir, sapphire.value());
    fs::create_directories(dir / "state" / "inbox");
    KioskProcess kiosk({GEMKIOSK_PATH, "--config", config.string(), "--seconds", "150"});
    ASSERT_TRUE(kiosk.wait_for_line("first frame on screen", 60s)) << kiosk.log();

    const auto copied = std::chrono::steady_clock::now();
    fs::copy(designs, dir / "state" / "inbox" / "designs", fs::copy_options::recursive);
    ASSERT_TRUE(kiosk.wait_for_line("showing catalogue 'designs'", 60s)) << kiosk.log();
    std::printf("copy to catalogue shown: %.2f s (settle_s, validation, install)\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - copied).count());
    // One error line names the stone, its file and what is wrong (logged just after).
    ASSERT_TRUE(kiosk.wait_for_line("left out", 10s)) << kiosk.log();
    const std::string log = kiosk.log();
    const auto at = log.find("stone 'broken' left out: broken.toml");
    ASSERT_NE(at, std::string::npos) << log;
    const auto line_start = log.rfind('\n', at) + 1;
    EXPECT_EQ(log.rfind("<3>", line_start), line_start) << log.substr(line_start, 200);
    EXPECT_NE(log.find("width_mm", at), std::string::npos) << log.substr(line_start, 200);

    // The emerald is on screen, drawn by the trace without tables; the snapshot waits for the
    // still view's frames to be averaged, as the reference is.
    const Image shown = settled_snapshot(kiosk, dir / "snapshots" / "snapshot.png");
    ASSERT_FALSE(shown.pixels.empty()) << kiosk.log();
    expect_shows(shown, designs, sapphire.value(), "the delivered design");

    kiosk.signal(SIGTERM);
    EXPECT_EQ(kiosk.wait(30s), 0) << kiosk.log();
}

}  // namespace
}  // namespace gem::kiosk_e2e
