// Staff bring a design, not a database: a catalogue whose stones are stone descriptions
// (config/stones/*.toml) is dropped into a running kiosk's inbox and its stone is shown at
// once, drawn by the exact trace; a design that cannot be read is left out with one line
// naming it, and the catalogue's other stones show. Checked on the real program's log and a
// snapshot against a reference drawn in this process.
#include <signal.h>

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <utility>

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

// A kiosk started with a catalogue of designs chooses its picture by measurement as it does
// for databases, over the trace's rungs alone (a design has no tables to fall back on), and
// sheds MSAA and glare when no rung holds the frame rate with them. Whether it sheds depends
// on the machine; which rungs it measures does not.
TEST(KioskDesigns, AStartupCatalogueOfDesignsIsProbedOverTheTraceAlone) {
    const fs::path dir = fresh_dir("design-probe");
    const fs::path designs = design_catalogue(dir / "designs");
    fs::path config = write_config(dir, designs, "[designs]\ntables = \"never\"\n");
    // The shared config draws tables as fast as it can; this kiosk chooses, against 60 Hz.
    std::string text;
    {
        std::ifstream in(config);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    for (auto [from, to] :
         {std::pair<std::string, std::string>{"method = \"table\"", "method = \"auto\""},
          {"headless_rate_hz = 0.0", "headless_rate_hz = 60.0"}}) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    }
    std::ofstream(config, std::ios::trunc) << text;
    KioskProcess kiosk({GEMKIOSK_PATH, "--config", config.string(), "--seconds", "60"});
    // The stone is shown at once, and measured between the frames shown.
    ASSERT_TRUE(kiosk.wait_for_line("first frame on screen", 60s)) << kiosk.log();
    ASSERT_TRUE(kiosk.wait_for_line("render.method auto: p90", 60s)) << kiosk.log();
    const std::string log = kiosk.log();
    const auto first_frame = log.find("first frame on screen");
    const auto at = log.find("render.method auto: p90 frame times trace ");
    EXPECT_LT(first_frame, at) << "the first frame waits for the probe";
    ASSERT_NE(at, std::string::npos) << log;
    const std::string line = log.substr(at, log.find('\n', at) - at);
    EXPECT_EQ(line.find("table"), std::string::npos) << line;
    EXPECT_EQ(line.find("phong"), std::string::npos) << line;
    EXPECT_NE(line.find("; using trace"), std::string::npos) << line;
    kiosk.signal(SIGTERM);
    EXPECT_EQ(kiosk.wait(30s), 0) << kiosk.log();
}

// The tables of a design that is not convex (the heart: the trace tests each of its triangles
// per bounce) are built in the background while its trace is on screen, switched to, and found
// again after a restart. The snapshot is checked against a picture drawn from the very
// database the kiosk built, by the table method in this process.
TEST(KioskDesigns, TablesAreBuiltInTheBackgroundAndReusedAfterARestart) {
    auto sapphire = test_catalogue("oval-sapphire");
    ASSERT_TRUE(sapphire.ok()) << sapphire.error();
    const fs::path dir = fresh_dir("design-tables");
    const fs::path delivery = dir / "delivery";
    fs::create_directories(delivery);
    fs::copy_file(fs::path(GEM_SOURCE_DIR) / "config/stones/heart-ruby.toml",
                  delivery / "heart.toml");
    std::ofstream(delivery / "catalogue.toml")
        << "[catalogue]\nname = \"hearts\"\n\n[[stone]]\nname = \"heart\"\n"
        << "design = \"heart.toml\"\n";
    // Tiny tables (32 and 64 px, every 20°, depth 4): a build of about a second.
    const fs::path config =
        write_config(dir, sapphire.value(),
                     "[designs]\ntables = \"always\"\nbuilder = \"" GEMTABLES_PATH
                     "\"\nlevel_px = 64\nspacing_deg = 20.0\ndepth = 4\n");
    fs::create_directories(dir / "state" / "inbox");
    fs::path built;
    {
        KioskProcess kiosk({GEMKIOSK_PATH, "--config", config.string(), "--seconds", "150"});
        ASSERT_TRUE(kiosk.wait_for_line("first frame on screen", 60s)) << kiosk.log();
        const auto copied = std::chrono::steady_clock::now();
        const auto since_copy = [&] {
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - copied).count();
        };
        fs::copy(delivery, dir / "state" / "inbox" / "hearts", fs::copy_options::recursive);
        ASSERT_TRUE(kiosk.wait_for_line("showing catalogue 'hearts'", 60s)) << kiosk.log();
        std::printf("copy to the design on screen (traced): %.2f s\n", since_copy());
        const std::string in_use = "design 'heart': drawn from its tables, ";
        ASSERT_TRUE(kiosk.wait_for_line(in_use, 120s)) << kiosk.log();
        std::printf("copy to its tables in use: %.2f s\n", since_copy());
        const std::string log = kiosk.log();
        EXPECT_NE(log.find("design 'heart': gemtables: running at idle CPU priority (SCHED_IDLE)"),
                  std::string::npos)
            << log;
        const auto at = log.find(in_use) + in_use.size();
        built = log.substr(at, log.find('\n', at) - at);
        ASSERT_TRUE(fs::exists(built)) << built;
        EXPECT_EQ(built.parent_path(), dir / "state" / "tables");

        // The same stone from the same database, as a catalogue of its own for the reference.
        const fs::path reference = dir / "reference";
        fs::create_directories(reference);
        fs::copy_file(built, reference / "heart.gemdb");
        std::ofstream(reference / "catalogue.toml")
            << "[catalogue]\nname = \"reference\"\n\n[[stone]]\nname = \"heart\"\n"
            << "database = \"heart.gemdb\"\nring = \"parametric\"\n";
        const Image shown = settled_snapshot(kiosk, dir / "snapshots" / "snapshot.png");
        ASSERT_FALSE(shown.pixels.empty()) << kiosk.log();
        expect_shows(shown, reference, sapphire.value(), "the design from its tables");
        kiosk.signal(SIGTERM);
        EXPECT_EQ(kiosk.wait(30s), 0) << kiosk.log();
    }
    // A restart shows the installed catalogue and takes the tables it finds, building nothing.
    const auto modified = fs::last_write_time(built);
    KioskProcess again({GEMKIOSK_PATH, "--config", config.string(), "--seconds", "60"});
    ASSERT_TRUE(again.wait_for_line("design 'heart': drawn from its tables", 60s)) << again.log();
    EXPECT_NE(again.log().find("checking the tables built before"), std::string::npos)
        << again.log();
    EXPECT_EQ(again.log().find("building its tables"), std::string::npos) << again.log();
    EXPECT_EQ(fs::last_write_time(built), modified);
    again.signal(SIGTERM);
    EXPECT_EQ(again.wait(30s), 0) << again.log();
}

}  // namespace
}  // namespace gem::kiosk_e2e
