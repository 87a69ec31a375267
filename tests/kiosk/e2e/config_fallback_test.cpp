// A config that does not parse never opens the kiosk: the real program, started once on a
// shop's good config with a chain's key and then on the same file with one line mistyped,
// keeps the shop's display settings and refuses an unsigned catalogue dropped in the inbox,
// saying why. And `gemkiosk --check-config` answers as `nginx -t` does.
#include <gtest/gtest.h>
#include <signal.h>

#include <fstream>

#include "e2e_fixture.hpp"
#include "kiosk_process.hpp"
#include "picture/image.hpp"

namespace gem::kiosk_e2e {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const fs::path kChainKey = fs::path(GEM_FIXTURES_DIR) / "signature" / "fixture.pub";

TEST(KioskConfig, ASyntaxErrorKeepsTheLastGoodConfigAndRefusesAnUnsignedDelivery) {
    auto sapphire = test_catalogue("oval-sapphire");
    auto diamond = test_catalogue("tolkowsky-diamond");
    ASSERT_TRUE(sapphire.ok() && diamond.ok());
    const fs::path dir = fresh_dir("config-fallback");
    const fs::path config = write_config(dir, sapphire.value());
    int line = 0;
    const std::string good =
        replaced(read_text(config), "[catalogue]\n",
                 "[catalogue]\ntrusted_keys = [\"" + kChainKey.string() + "\"]\n", &line);
    write_text(config, good);
    const fs::path state = dir / "state";
    fs::create_directories(state / "inbox");

    // Started on the good config: it is kept, with the key.
    const Finished first = run_kiosk({GEMKIOSK_PATH, "--config", config.string(), "--state-dir",
                                      state.string(), "--frames", "2"},
                                     120s);
    ASSERT_EQ(first.status, 0) << first.log;
    EXPECT_NE(line_with(first.log, "kept as the last good one"), "") << first.log;
    ASSERT_TRUE(fs::exists(state / "last-good-config.toml"));

    // One unrelated line mistyped, as staff do; the kiosk restarted.
    int broken_line = 0;
    write_text(config, replaced(good, "depth = 6\n", "depth = 6 x\n", &broken_line));
    KioskProcess kiosk({GEMKIOSK_PATH, "--config", config.string(), "--state-dir", state.string(),
                        "--seconds", "150", "--snapshot-last"});
    ASSERT_TRUE(kiosk.wait_for_line("first frame on screen", 60s)) << kiosk.log();
    const std::string fallback = line_with(kiosk.log(), "is set aside");
    EXPECT_EQ(fallback.rfind(
                  "<3>gemkiosk: " + config.string() + ":" + std::to_string(broken_line) + ":", 0),
              0u)
        << kiosk.log();
    EXPECT_NE(fallback.find("the last good config"), std::string::npos) << fallback;
    EXPECT_NE(
        line_with(kiosk.log(), "catalogues must be signed by a trusted key: 6210369F81C2ADCE"), "")
        << kiosk.log();

    // A stranger's catalogue, unsigned, dropped in the inbox: refused, with the reason.
    fs::copy(diamond.value(), state / "inbox" / "evil", fs::copy_options::recursive);
    ASSERT_TRUE(kiosk.wait_for_line("not installed", 60s)) << kiosk.log();
    const std::string refused = line_with(kiosk.log(), "not installed");
    EXPECT_EQ(refused.rfind("<3>gemkiosk: catalogue at " + (state / "inbox" / "evil").string() +
                                " not installed: the config is set aside (" + config.string() +
                                ":" + std::to_string(broken_line) + ":",
                            0),
              0u)
        << refused;
    EXPECT_TRUE(fs::exists(state / "inbox" / "evil" / "catalogue.toml")) << "left where it was";

    kiosk.signal(SIGTERM);
    EXPECT_EQ(kiosk.wait(30s), 0) << kiosk.log();
    EXPECT_EQ(kiosk.log().find("installed as"), std::string::npos) << kiosk.log();
    EXPECT_EQ(kiosk.log().find("showing catalogue 'tolkowsky-diamond'"), std::string::npos);
    // The shop's display settings stood: the kept config's picture size and snapshot folder,
    // not the defaults' 1920 × 1080 in /var/lib/gemkiosk/snapshots.
    auto last = read_png(dir / "snapshots" / "last.png");
    ASSERT_TRUE(last.ok()) << kiosk.log();
    EXPECT_EQ(last.value().width, kWidth);
    EXPECT_EQ(last.value().height, kHeight);
}

struct Checked {
    int status = -1;
    std::string log;
};

Checked check(const fs::path& file) {
    const Finished run = run_kiosk({GEMKIOSK_PATH, "--check-config", file.string()}, 60s);
    return {run.status, run.log};
}

TEST(KioskConfig, CheckConfigPassesTheShippedFileAndNamesEveryProblemOfABrokenOne) {
    const fs::path shipped = fs::path(GEM_SOURCE_DIR) / "config" / "gemkiosk.toml";
    const Checked good = check(shipped);
    EXPECT_EQ(good.status, 0) << good.log;
    EXPECT_EQ(good.log, shipped.string() + ": no problems\n");

    const fs::path dir = fresh_dir("check-config");
    const std::string text = read_text(shipped);
    int line = 0;

    const fs::path syntax = dir / "syntax.toml";
    write_text(syntax, replaced(text, "msaa = 4\n", "msaa = 4 x\n", &line));
    const Checked a = check(syntax);
    EXPECT_EQ(a.status, 1) << a.log;
    EXPECT_EQ(a.log.rfind(syntax.string() + ":" + std::to_string(line) + ":", 0), 0u) << a.log;
    EXPECT_NE(a.log.find("1 problem; the kiosk would set the whole file aside"), std::string::npos)
        << a.log;

    const fs::path values = dir / "values.toml";
    int rotation_line = 0;
    std::string edited = replaced(text, "rotation = 0\n", "rotation = 45\n", &rotation_line);
    edited = replaced(edited, "[picture]\n", "[picture]\nfog = 1\n", &line);
    write_text(values, edited);
    const Checked b = check(values);
    EXPECT_EQ(b.status, 1) << b.log;
    EXPECT_NE(b.log.find(values.string() + ":" + std::to_string(rotation_line) +
                         ": display.rotation: expected one of 0, 90, 180, 270\n"),
              std::string::npos)
        << b.log;
    EXPECT_NE(b.log.find(values.string() + ":" + std::to_string(line + 1) +
                         ": picture.fog: unknown key\n"),
              std::string::npos)
        << b.log;
    EXPECT_NE(b.log.find("2 problems"), std::string::npos) << b.log;

    const fs::path keys = dir / "keys.toml";
    write_text(keys,
               replaced(text, "trusted_keys = []\n", "trusted_keys = [\"chain.pub\"]\n", &line));
    write_text(dir / "chain.pub", "untrusted comment: not a key\nhello\n");
    const Checked c = check(keys);
    EXPECT_EQ(c.status, 1) << c.log;
    EXPECT_NE(c.log.find("trusted key left out: " + (dir / "chain.pub").string() +
                         ": not a minisign public key"),
              std::string::npos)
        << c.log;
}

}  // namespace
}  // namespace gem::kiosk_e2e
