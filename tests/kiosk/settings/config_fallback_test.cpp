// What the kiosk runs on when its config file is not as it should be: the last good config
// and its keys stand in for a file that does not parse, no delivery is accepted until it is
// fixed, and a typo never drops the keys. Each case is written out by hand below and checked
// against the values it sets, not against what the loader returns for another file.
#include <gtest/gtest.h>

#include "catalogue_test_support.hpp"
#include "settings/config_fallback.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using catalogue_test::fresh_dir;
using catalogue_test::write_text;

// A shop's config: a connector, a rotation, a looks preset, a chain's key.
const std::string kShopConfig =
    "[display]\n"
    "connector = \"HDMI-A-2\"\n"
    "rotation = 90\n"
    "[picture]\n"
    "msaa = 2\n"
    "[catalogue]\n"
    "trusted_keys = [\"chain.pub\"]\n";
const std::string kChainKey =
    "untrusted comment: minisign public key 0123456789ABCDEF\n"
    "RWTvzasSeHgpAQbV7wtUqKVeBRpCYq0sMh6+yfGVb9r0ErPNDhQbBTba\n";

// The shop's config with `from` (which it holds once) written as `to`.
std::string shop_config_with(const std::string& from, const std::string& to) {
    std::string text = kShopConfig;
    text.replace(text.find(from), from.size(), to);
    return text;
}

struct Shop {
    fs::path dir;
    fs::path config;
    fs::path state;
};

// A kiosk that has started once on the shop's good config and kept it.
Shop shop_with_a_kept_config(const std::string& name) {
    Shop shop{fresh_dir(name), {}, {}};
    shop.config = shop.dir / "etc" / "gemkiosk.toml";
    shop.state = shop.dir / "state";
    write_text(shop.config, kShopConfig);
    write_text(shop.dir / "etc" / "chain.pub", kChainKey);
    const ResolvedConfig first = resolve_config(shop.config, shop.state);
    EXPECT_TRUE(first.errors.empty()) << first.errors.front();
    EXPECT_TRUE(first.good.has_value());
    if (first.good) {
        auto kept = keep_last_good_config(shop.state, *first.good);
        EXPECT_TRUE(kept.ok() && kept.value()) << (kept ? "" : kept.error());
    }
    return shop;
}

TEST(LastGoodConfig, KeepsTheTextAndKeysAsTheyWereAndWritesOnlyAChange) {
    const fs::path state = fresh_dir("last-good-roundtrip");
    // Whatever a TOML file may hold, quotes of every kind, escapes, tabs, a control byte.
    const KeptConfig kept{"/etc/gemkiosk/gemkiosk.toml",
                          "a = '''x''' # \"\"\" \\ \t\x01\r\n[b]\nc = \"\\u00e9\"\n",
                          {{"/etc/gemkiosk/chain.pub", kChainKey}, {"second.pub", ""}}};
    auto written = keep_last_good_config(state, kept);
    ASSERT_TRUE(written.ok()) << written.error();
    EXPECT_TRUE(written.value());
    auto read = read_last_good_config(state);
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(read.value(), kept);
    const auto when = fs::last_write_time(state / kLastGoodConfigName);
    auto again = keep_last_good_config(state, kept);
    ASSERT_TRUE(again.ok());
    EXPECT_FALSE(again.value()) << "the same config is not written again";
    EXPECT_EQ(fs::last_write_time(state / kLastGoodConfigName), when);
}

TEST(LastGoodConfig, NoneKeptOrDamagedIsAnErrorNamingTheFile) {
    const fs::path state = fresh_dir("last-good-damaged");
    auto none = read_last_good_config(state);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().find((state / kLastGoodConfigName).string()), std::string::npos);
    write_text(state / kLastGoodConfigName, "source = \"/etc/x.toml\"\nconfig = \"\"\"cut sh");
    auto damaged = read_last_good_config(state);
    ASSERT_FALSE(damaged.ok());
    EXPECT_NE(damaged.error().find("damaged"), std::string::npos) << damaged.error();
    write_text(state / kLastGoodConfigName, "source = \"/etc/x.toml\"\n");
    auto missing = read_last_good_config(state);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("'config' is missing"), std::string::npos) << missing.error();
}

// The format as the header documents it, written by hand (tests/fixtures/config), read back
// as the shop's settings and key; a config set aside falls back to it.
TEST(LastGoodConfig, AHandWrittenCopyIsReadAndStandsInForABrokenFile) {
    const fs::path dir = fresh_dir("last-good-fixture");
    fs::create_directories(dir / "state");
    fs::copy_file(fs::path(GEM_FIXTURES_DIR) / "config" / kLastGoodConfigName,
                  dir / "state" / kLastGoodConfigName);
    write_text(dir / "gemkiosk.toml", "[display]\nrotation = 90 degrees\n");
    const ResolvedConfig resolved = resolve_config(dir / "gemkiosk.toml", dir / "state");
    EXPECT_EQ(resolved.config.display.connector, "HDMI-A-2");
    EXPECT_EQ(resolved.config.display.rotation_deg, 270);
    EXPECT_DOUBLE_EQ(resolved.config.input.calibration[0], 1.02);
    EXPECT_DOUBLE_EQ(resolved.config.input.calibration[5], 0.02);
    // The kept config's relative key path resolves beside where it was read.
    ASSERT_EQ(resolved.config.catalogue.trusted_keys.size(), 1u);
    EXPECT_EQ(resolved.config.catalogue.trusted_keys[0], fs::path("/etc/gemkiosk/chain.pub"));
    ASSERT_EQ(resolved.trusted_keys.size(), 1u);
    EXPECT_EQ(resolved.trusted_keys[0].file, fs::path("/etc/gemkiosk/chain.pub"));
    EXPECT_EQ(resolved.trusted_keys[0].text.rfind("untrusted comment: minisign public key "
                                                  "6210369F81C2ADCE\nRWTOrcKB",
                                                  0),
              0u);
    EXPECT_TRUE(resolved.signatures_required);
}

TEST(ConfigFallback, AGoodConfigIsUsedAndOfferedForKeeping) {
    const fs::path dir = fresh_dir("fallback-good");
    write_text(dir / "gemkiosk.toml", kShopConfig);
    write_text(dir / "chain.pub", kChainKey);
    const ResolvedConfig resolved = resolve_config(dir / "gemkiosk.toml", dir / "state");
    EXPECT_TRUE(resolved.errors.empty());
    EXPECT_EQ(resolved.config.display.connector, "HDMI-A-2");
    EXPECT_TRUE(resolved.deliveries_refused_because.empty());
    EXPECT_TRUE(resolved.signatures_required);
    ASSERT_EQ(resolved.trusted_keys.size(), 1u);
    EXPECT_EQ(resolved.trusted_keys[0].text, kChainKey);
    ASSERT_TRUE(resolved.good.has_value());
    EXPECT_EQ(resolved.good->text, kShopConfig);
    EXPECT_EQ(resolved.good->keys, resolved.trusted_keys);
}

// The issue's own case: one unrelated line mistyped. The shop's display settings and keys
// stand, and deliveries are refused; the one line names the file, the line and the fallback.
TEST(ConfigFallback, ASyntaxErrorFallsBackToTheLastGoodConfigAndItsKeys) {
    const Shop shop = shop_with_a_kept_config("fallback-syntax");
    write_text(shop.config, shop_config_with("msaa = 2", "msaa = 4 x"));
    fs::remove(shop.dir / "etc" / "chain.pub");  // even the key file gone: the kept copy stands

    const ResolvedConfig resolved = resolve_config(shop.config, shop.state);
    EXPECT_EQ(resolved.config.display.connector, "HDMI-A-2");
    EXPECT_EQ(resolved.config.display.rotation_deg, 90);
    EXPECT_EQ(resolved.config.picture.msaa, 2);
    EXPECT_TRUE(resolved.signatures_required);
    ASSERT_EQ(resolved.trusted_keys.size(), 1u);
    EXPECT_EQ(resolved.trusted_keys[0].text, kChainKey);
    EXPECT_FALSE(resolved.good.has_value()) << "a broken file is never kept";
    ASSERT_EQ(resolved.errors.size(), 1u);
    const std::string& line = resolved.errors[0];
    EXPECT_EQ(line.rfind(shop.config.string() + ":5:", 0), 0u) << line;
    EXPECT_NE(line.find("the last good config (" + shop.config.string() + " as kept in " +
                        (shop.state / kLastGoodConfigName).string() + ") is used"),
              std::string::npos)
        << line;
    EXPECT_NE(line.find("no new catalogue is accepted"), std::string::npos) << line;
    EXPECT_NE(resolved.deliveries_refused_because.find(shop.config.string() + ":5:"),
              std::string::npos)
        << resolved.deliveries_refused_because;
}

TEST(ConfigFallback, AnUnreadableFileIsSetAsideAsOneThatDoesNotParse) {
    const Shop shop = shop_with_a_kept_config("fallback-unreadable");
    fs::remove(shop.config);
    const ResolvedConfig resolved = resolve_config(shop.config, shop.state);
    EXPECT_EQ(resolved.config.display.rotation_deg, 90);
    EXPECT_EQ(resolved.trusted_keys.size(), 1u);
    EXPECT_FALSE(resolved.deliveries_refused_because.empty());
    ASSERT_EQ(resolved.errors.size(), 1u);
    EXPECT_EQ(resolved.errors[0].rfind(shop.config.string() + ": cannot open", 0), 0u)
        << resolved.errors[0];
}

TEST(ConfigFallback, WithNothingKeptTheDefaultsStandAndDeliveriesAreStillRefused) {
    const fs::path dir = fresh_dir("fallback-nothing-kept");
    write_text(dir / "gemkiosk.toml", "[display\nrotation = 90\n");
    const ResolvedConfig resolved = resolve_config(dir / "gemkiosk.toml", dir / "state");
    EXPECT_EQ(resolved.config.display.rotation_deg, 0);
    EXPECT_FALSE(resolved.deliveries_refused_because.empty());
    ASSERT_EQ(resolved.errors.size(), 1u);
    EXPECT_NE(resolved.errors[0].find("built-in defaults are used, as no good config was kept"),
              std::string::npos)
        << resolved.errors[0];
}

// A line that parses but is bad keeps its key's default, as before; deliveries are accepted,
// and the file is not kept.
TEST(ConfigFallback, ABadValueKeepsItsDefaultAndTheRestApplies) {
    const Shop shop = shop_with_a_kept_config("fallback-bad-value");
    write_text(shop.config, shop_config_with("rotation = 90", "rotation = 45"));
    const ResolvedConfig resolved = resolve_config(shop.config, shop.state);
    ASSERT_EQ(resolved.errors.size(), 1u);
    EXPECT_EQ(resolved.errors[0],
              shop.config.string() + ":3: display.rotation: expected one of 0, 90, 180, 270");
    EXPECT_EQ(resolved.config.display.rotation_deg, 0);
    EXPECT_EQ(resolved.config.display.connector, "HDMI-A-2");
    EXPECT_TRUE(resolved.deliveries_refused_because.empty());
    EXPECT_FALSE(resolved.good.has_value());
}

// `[catalouge]`: the file parses, the table is unknown, and it lists no key. The last good
// config's keys are still required.
TEST(ConfigFallback, AMisspeltCatalogueTableDoesNotDropTheKeys) {
    const Shop shop = shop_with_a_kept_config("fallback-misspelt");
    write_text(shop.config, shop_config_with("[catalogue]", "[catalouge]"));
    const ResolvedConfig resolved = resolve_config(shop.config, shop.state);
    EXPECT_TRUE(resolved.signatures_required);
    ASSERT_EQ(resolved.trusted_keys.size(), 1u);
    EXPECT_EQ(resolved.trusted_keys[0].text, kChainKey);
    ASSERT_EQ(resolved.errors.size(), 2u);
    EXPECT_EQ(resolved.errors[0], shop.config.string() + ":6: catalouge: unknown key");
    EXPECT_NE(resolved.errors[1].find("lists no trusted key but has errors"), std::string::npos)
        << resolved.errors[1];
    // A clean config that drops the keys on purpose is obeyed.
    write_text(shop.config, "[display]\nrotation = 90\n");
    const ResolvedConfig dropped = resolve_config(shop.config, shop.state);
    EXPECT_TRUE(dropped.errors.empty());
    EXPECT_FALSE(dropped.signatures_required);
}

TEST(ConfigFallback, AKeyFileThatCannotBeReadIsNamedAndSignaturesStayRequired) {
    const fs::path dir = fresh_dir("fallback-key-unreadable");
    write_text(dir / "huge.pub", std::string(5000, 'R'));  // a key file is two short lines
    write_text(dir / "gemkiosk.toml",
               "[catalogue]\ntrusted_keys = [\"chain.pub\", \"/dev/zero\", \"" + dir.string() +
                   "\", \"huge.pub\"]\n");
    const ResolvedConfig resolved = resolve_config(dir / "gemkiosk.toml", dir / "state");
    EXPECT_TRUE(resolved.signatures_required);
    EXPECT_TRUE(resolved.trusted_keys.empty());
    EXPECT_FALSE(resolved.good.has_value());
    ASSERT_EQ(resolved.errors.size(), 4u);
    EXPECT_EQ(resolved.errors[0], "trusted key left out: " + (dir / "chain.pub").string() +
                                      ": cannot open (No such file or directory); catalogues "
                                      "signed with it will be refused");
    EXPECT_NE(resolved.errors[1].find("/dev/zero: not a regular file"), std::string::npos);
    EXPECT_NE(resolved.errors[2].find(dir.string() + ": not a regular file"), std::string::npos);
    EXPECT_NE(resolved.errors[3].find("huge.pub: not a key file (too large)"), std::string::npos)
        << resolved.errors[3];
}

}  // namespace
}  // namespace gem::kiosk
