// What the kiosk does with bad surroundings: no display, a config with bad lines, no input
// devices, a damaged recording. Each gets one clear line naming the thing and the fault, and
// the kiosk keeps running where it can.
#include <gtest/gtest.h>

#include <fstream>

#include "e2e_fixture.hpp"
#include "kiosk_process.hpp"

namespace gem::kiosk_e2e {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

TEST(KioskFaults, NoDisplayIsReportedOnceAndTheKioskKeepsRunning) {
    auto catalogue = test_catalogue("tolkowsky-diamond");
    ASSERT_TRUE(catalogue.ok());
    const fs::path dir = fresh_dir("no-display");
    const fs::path config = write_config(dir, catalogue.value());
    // This machine has no /dev/dri: the DRM backend must say so and keep retrying, alive.
    const Finished run = run_kiosk(
        {GEMKIOSK_PATH, "--config", config.string(), "--backend", "drm", "--seconds", "3"}, 60s);
    EXPECT_EQ(run.status, 0) << run.log;
    const std::string line = line_with(run.log, "trying again");
    EXPECT_EQ(line.rfind("<3>", 0), 0u) << run.log;
    EXPECT_NE(line.find("/dev/dri"), std::string::npos) << line;
    // Said once, not every retry.
    EXPECT_EQ(run.log.find("trying again", run.log.find("trying again") + 1), std::string::npos);
}

TEST(KioskFaults, BadConfigLinesAreNamedAndTheRestStillApplies) {
    auto catalogue = test_catalogue("tolkowsky-diamond");
    ASSERT_TRUE(catalogue.ok());
    const fs::path dir = fresh_dir("bad-config");
    // Appended after write_config's lines: an unknown table with a key.
    const fs::path config = write_config(dir, catalogue.value(), "[shop]\nopening = 9\n");
    std::ifstream in(config);
    int lines = 0;
    for (std::string l; std::getline(in, l);) ++lines;
    const Finished run = run_kiosk(
        {GEMKIOSK_PATH, "--config", config.string(), "--frames", "3", "--snapshot-last"}, 120s);
    EXPECT_EQ(run.status, 0) << run.log;
    // The unknown table is named with its line: the file's last two lines.
    const std::string line = line_with(run.log, "gemkiosk.toml:");
    EXPECT_NE(line.find("gemkiosk.toml:" + std::to_string(lines - 1)), std::string::npos)
        << run.log;
    EXPECT_NE(line.find("shop"), std::string::npos) << line;
    // The rest of the file applied: the headless size came from it.
    auto last = read_png(dir / "snapshots" / "last.png");
    ASSERT_TRUE(last.ok()) << run.log;
    EXPECT_EQ(last.value().width, kWidth);
    EXPECT_EQ(last.value().height, kHeight);
}

TEST(KioskFaults, NoInputDevicesIsOneLineAndTheKioskStillDraws) {
    auto catalogue = test_catalogue("tolkowsky-diamond");
    ASSERT_TRUE(catalogue.ok());
    const fs::path dir = fresh_dir("no-input");
    const fs::path config = write_config(dir, catalogue.value());
    const Finished run =
        run_kiosk({GEMKIOSK_PATH, "--config", config.string(), "--frames", "3"}, 120s);
    EXPECT_EQ(run.status, 0) << run.log;
    EXPECT_NE(line_with(run.log, (dir / "no-input").string()), "") << run.log;
    EXPECT_NE(run.log.find("3 frames"), std::string::npos) << run.log;
}

TEST(KioskFaults, DamagedRecordingIsRefusedWithFileAndLine) {
    auto catalogue = test_catalogue("tolkowsky-diamond");
    ASSERT_TRUE(catalogue.ok());
    const fs::path dir = fresh_dir("bad-recording");
    const fs::path config = write_config(dir, catalogue.value());
    // The start of a synthetic recording (description and some events), then a line that is
    // not an event.
    std::ifstream real(fs::path(GEM_FIXTURES_DIR) / "kiosk" / "atmel-drag-right.events");
    std::ofstream bad(dir / "bad.events");
    std::string l;
    int n = 0;
    while (std::getline(real, l)) {
        bad << l << "\n";
        ++n;
        if (l.rfind("E:", 0) == 0 && n > 40) break;
    }
    bad << "E: 0.5 0003 zz 12\n";
    bad.close();
    const Finished run = run_kiosk(
        {GEMKIOSK_PATH, "--config", config.string(), "--replay", (dir / "bad.events").string()},
        60s);
    EXPECT_EQ(run.status, 1) << run.log;
    EXPECT_NE(line_with(run.log, "bad.events:" + std::to_string(n + 1)), "") << run.log;
}

}  // namespace
}  // namespace gem::kiosk_e2e

namespace gem::kiosk_e2e {
namespace {

TEST(KioskFrameRate, FrameRateCapIsNeverExceeded) {
    // render.frame_rate_hz = 10 over a 2-second run: at most 21 frames however fast the
    // machine draws (uncapped, this small picture draws at 80+ frames/s here). Only the upper
    // bound is checked: a slow machine may draw fewer.
    auto catalogue = test_catalogue("tolkowsky-diamond");
    ASSERT_TRUE(catalogue.ok());
    const fs::path dir = fresh_dir("frame-rate-cap");
    std::string text;
    {
        std::ifstream in(write_config(dir, catalogue.value()));
        for (std::string l; std::getline(in, l);) {
            text += l + "\n";
            if (l == "[render]") text += "frame_rate_hz = 10.0\n";
        }
    }
    std::ofstream(dir / "gemkiosk.toml") << text;
    const fs::path csv = dir / "frames.csv";
    const Finished run = run_kiosk({GEMKIOSK_PATH, "--config", (dir / "gemkiosk.toml").string(),
                                    "--seconds", "2", "--stats", csv.string()},
                                   std::chrono::seconds(60));
    ASSERT_EQ(run.status, 0) << run.log;
    std::ifstream rows(csv);
    int frames = -1;  // the header
    for (std::string l; std::getline(rows, l);) ++frames;
    EXPECT_GT(frames, 0);
    EXPECT_LE(frames, 21) << run.log;
}

}  // namespace
}  // namespace gem::kiosk_e2e
