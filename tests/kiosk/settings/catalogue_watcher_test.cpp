// The inbox watcher end to end, on real directories with a real inotify, eventfd and thread:
// a good catalogue is installed and handed over, a damaged or half-copied one never becomes
// current and is set aside in the inbox as NAME.rejected, one that cannot be (a stick) is not
// validated again until it changes, nor is a package's folder dpkg is unpacking looked at, a
// copy that fails on a full disk leaves the current one, and old copies are removed.

#include <gtest/gtest.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <thread>

#include "catalogue/catalogue_store.hpp"
#include "catalogue/catalogue_watcher.hpp"
#include "catalogue/validate.hpp"
#include "catalogue_test_support.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using namespace catalogue_test;
using namespace std::chrono_literals;

CatalogueOptions options_for(const fs::path& root, std::chrono::milliseconds settle) {
    CatalogueOptions o;
    o.inbox_dir = root / "inbox";
    o.state_dir = root / "state";
    o.default_catalogue = root / "default";
    o.settle_time = settle;
    fs::create_directories(o.inbox_dir);
    fs::create_directories(o.state_dir);
    return o;
}

std::unique_ptr<CatalogueWatcher> start(const CatalogueOptions& o) {
    auto watcher = CatalogueWatcher::start(o);
    EXPECT_TRUE(watcher.ok()) << watcher.error();
    return std::move(watcher).value();
}

// The main loop's view: the event fd becomes readable (up to 60 s on a loaded machine).
bool switch_signalled(const CatalogueWatcher& w) {
    pollfd p{w.event_fd(), POLLIN, 0};
    return ::poll(&p, 1, 60'000) == 1;
}

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::uint8_t> damaged_database(std::uint32_t* view) {
    std::vector<std::uint8_t> bytes = read_bytes(tiny_database());
    *view = header_view_count(bytes) - 1;
    const PayloadSpan span = payload_span(bytes, *view, 0, 1);
    bytes.at(span.offset + span.bytes / 3) ^= 0x01;
    return bytes;
}

// Installs a good catalogue and returns its copy.
fs::path install_good(CatalogueWatcher& w, const CatalogueOptions& o, const std::string& name) {
    const auto before = w.counters().installs;
    write_catalogue(o.inbox_dir / name, name);
    EXPECT_TRUE(wait_until([&] { return w.counters().installs > before; }));
    auto taken = w.take_switch();
    EXPECT_TRUE(taken.has_value());
    return taken ? taken->directory : fs::path();
}

TEST(CatalogueWatcher, ValidCatalogueIsInstalledAndHandedOver) {
    const fs::path root = fresh_dir("watch-valid");
    const CatalogueOptions o = options_for(root, 300ms);
    auto w = start(o);
    write_catalogue(o.inbox_dir / "spring", "spring");
    ASSERT_TRUE(switch_signalled(*w));
    std::optional<Catalogue> taken = w->take_switch();
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->name, "spring");
    EXPECT_EQ(taken->directory, fs::canonical(o.state_dir / "current"));
    EXPECT_EQ(taken->directory.parent_path(), fs::canonical(o.state_dir / "catalogues"));
    ASSERT_EQ(taken->stones.size(), 1u);
    ASSERT_NE(taken->stones[0].opened, nullptr);
    // What is mapped is the copy, not the inbox (which may be a stick about to be pulled).
    EXPECT_EQ(taken->stones[0].opened->path(), taken->directory / "stones" / "round.gemdb");
    EXPECT_EQ(read_bytes(taken->stones[0].opened->path()), read_bytes(tiny_database()));
    EXPECT_FALSE(w->take_switch().has_value()) << "one switch, handed over once";
    pollfd p{w->event_fd(), POLLIN, 0};
    EXPECT_EQ(::poll(&p, 1, 0), 0) << "take_switch() drains the event fd";
    EXPECT_EQ(w->counters().rejections, 0u);
}

TEST(CatalogueWatcher, CatalogueAtAStickRootIsInstalledAndSurvivesThePull) {
    const fs::path root = fresh_dir("watch-stick");
    CatalogueOptions o = options_for(root, 300ms);
    o.extra_dirs = {root / "media" / "usb"};
    write_catalogue(root / "media" / "usb", "from-stick");
    auto w = start(o);
    ASSERT_TRUE(switch_signalled(*w));
    auto taken = w->take_switch();
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(taken->name, "from-stick");
    fs::remove_all(root / "media" / "usb");
    auto again = validate_catalogue(o.state_dir / "current");
    EXPECT_TRUE(again.ok()) << again.error();
}

TEST(CatalogueWatcher, DamagedDatabasesAreRejectedAndTheCurrentStays) {
    const fs::path root = fresh_dir("watch-damaged");
    const CatalogueOptions o = options_for(root, 300ms);
    auto w = start(o);
    const fs::path good = install_good(*w, o, "spring");
    ASSERT_FALSE(good.empty());
    StderrCapture capture;

    std::uint32_t view = 0;
    const std::vector<std::uint8_t> damaged = damaged_database(&view);
    write_text(o.inbox_dir / "autumn" / "catalogue.toml", one_stone_manifest("autumn"));
    write_bytes(o.inbox_dir / "autumn" / "stones" / "round.gemdb", damaged);
    ASSERT_TRUE(wait_until([&] { return w->counters().rejections == 1; }));
    EXPECT_NE(capture.text().find("catalogue 'autumn' rejected: stones/round.gemdb: view " +
                                  std::to_string(view) + " level 0: checksum mismatch (from " +
                                  (o.inbox_dir / "autumn").string() + ")"),
              std::string::npos)
        << capture.text();

    auto truncated = read_bytes(tiny_database());
    const std::size_t full = truncated.size();
    truncated.resize(full - 1000);
    write_text(o.inbox_dir / "winter" / "catalogue.toml", one_stone_manifest("winter"));
    write_bytes(o.inbox_dir / "winter" / "stones" / "round.gemdb", truncated);
    ASSERT_TRUE(wait_until([&] { return w->counters().rejections == 2; }));
    EXPECT_NE(
        capture.text().find("catalogue 'winter' rejected: stones/round.gemdb: truncated: " +
                            std::to_string(full - 1000) + " of " + std::to_string(full) + " bytes"),
        std::string::npos)
        << capture.text();

    EXPECT_EQ(fs::canonical(o.state_dir / "current"), good);
    EXPECT_FALSE(w->take_switch().has_value());
    EXPECT_EQ(entries(o.state_dir / "catalogues"), std::vector<std::string>{"spring-1"})
        << "a refused catalogue is never copied";
    EXPECT_EQ(w->counters().installs, 1u);
}

// While the kiosk's config is set aside, no delivery is installed, however good: each gets one
// line saying why and stays where staff put it (not set aside, not remembered), so a kiosk
// started on a fixed config installs it.
TEST(CatalogueWatcher, WhileDeliveriesAreRefusedAGoodCatalogueStaysInTheInbox) {
    const fs::path root = fresh_dir("watch-refused");
    CatalogueOptions o = options_for(root, 300ms);
    o.deliveries_refused_because = "the config is set aside (gemkiosk.toml:3:9: ...)";
    StderrCapture capture;
    {
        auto w = start(o);
        write_catalogue(o.inbox_dir / "spring", "spring");
        ASSERT_TRUE(wait_until([&] { return w->counters().rejections == 1; }));
        const auto scans = w->counters().scans;
        w->rescan();
        ASSERT_TRUE(wait_until([&] { return w->counters().scans > scans; }));
        EXPECT_EQ(w->counters().validations, 0u) << "never opened";
        EXPECT_EQ(w->counters().installs, 0u);
        EXPECT_EQ(w->counters().rejections, 1u) << "said once, not at every scan";
    }
    const std::string line = "<3>gemkiosk: catalogue at " + (o.inbox_dir / "spring").string() +
                             " not installed: " + o.deliveries_refused_because +
                             "; it is left where it is\n";
    EXPECT_NE(capture.text().find(line), std::string::npos) << capture.text();
    EXPECT_EQ(entries(o.inbox_dir), std::vector<std::string>{"spring"});
    EXPECT_FALSE(fs::exists(o.state_dir / "current"));
    EXPECT_FALSE(fs::exists(o.state_dir / kRefusedSources));

    // Started again on a good config: the same catalogue is installed.
    o.deliveries_refused_because.clear();
    auto w = start(o);
    ASSERT_TRUE(switch_signalled(*w));
    EXPECT_EQ(w->take_switch()->name, "spring");
}

// A catalogue on a stick cannot be set aside: it is refused once, remembered by fingerprint,
// not validated again by a rescan nor after a restart, and looked at again once it changes.
TEST(CatalogueWatcher, UnchangedRejectedDirectoryIsNotValidatedAgain) {
    const fs::path root = fresh_dir("watch-remember");
    CatalogueOptions o = options_for(root, 300ms);
    o.extra_dirs = {root / "stick"};
    std::uint32_t view = 0;
    const std::vector<std::uint8_t> damaged = damaged_database(&view);
    write_text(root / "stick" / "autumn" / "catalogue.toml", one_stone_manifest("autumn"));
    write_bytes(root / "stick" / "autumn" / "stones" / "round.gemdb", damaged);
    {
        StderrCapture capture;
        auto w = start(o);
        ASSERT_TRUE(wait_until([&] { return w->counters().rejections == 1; }));
        EXPECT_EQ(w->counters().validations, 1u);
        // Each rescan is a full pass over the inbox (SIGHUP); the directory is unchanged.
        for (int i = 0; i < 3; ++i) {
            const auto scans = w->counters().scans;
            w->rescan();
            ASSERT_TRUE(wait_until([&] { return w->counters().scans > scans; }));
        }
        EXPECT_EQ(w->counters().validations, 1u);
        EXPECT_EQ(w->counters().rejections, 1u);
        EXPECT_NE(
            capture.text().find("checksum mismatch (from " + (root / "stick" / "autumn").string() +
                                "); not reported again until it changes"),
            std::string::npos)
            << capture.text();
        EXPECT_TRUE(fs::exists(root / "stick" / "autumn" / "catalogue.toml"))
            << "a stick's catalogue stays as it is";
    }
    {
        // A restart (a power cut, an update) does not report it again.
        StderrCapture capture;
        auto w = start(o);
        const auto scans = w->counters().scans;
        w->rescan();
        ASSERT_TRUE(wait_until([&] { return w->counters().scans > scans; }));
        EXPECT_EQ(w->counters().validations, 0u);
        EXPECT_EQ(capture.text().find("rejected"), std::string::npos) << capture.text();
        // Staff replace the damaged file: that is a change, so it is looked at again.
        write_bytes(root / "stick" / "autumn" / "stones" / "round.gemdb",
                    read_bytes(tiny_database()));
        ASSERT_TRUE(wait_until([&] { return w->counters().installs == 1; }));
        EXPECT_EQ(w->counters().validations, 1u);
        EXPECT_EQ(w->take_switch()->name, "autumn");
    }
}

// A catalogue package's folder while dpkg unpacks it (a file still under its *.dpkg-new name,
// as after a power cut mid-upgrade) is not looked at however long it stays so: no refusal,
// nothing installed. Once the file has its name, it is installed.
TEST(CatalogueWatcher, AFolderDpkgIsUnpackingIsNotLookedAt) {
    const fs::path root = fresh_dir("watch-dpkg");
    CatalogueOptions o = options_for(root, 200ms);
    o.extra_dirs = {root / "packages"};
    const fs::path dir = root / "packages" / "gemkiosk-catalogue-spring";
    write_text(dir / "catalogue.toml", one_stone_manifest("spring"));
    write_bytes(dir / "stones" / "round.gemdb.dpkg-new", read_bytes(tiny_database()));
    auto w = start(o);
    std::this_thread::sleep_for(1500ms);
    EXPECT_EQ(w->counters().validations, 0u);
    EXPECT_EQ(w->counters().rejections, 0u);
    fs::rename(dir / "stones" / "round.gemdb.dpkg-new", dir / "stones" / "round.gemdb");
    ASSERT_TRUE(wait_until([&] { return w->counters().installs == 1; }));
    EXPECT_EQ(w->counters().rejections, 0u);
    EXPECT_EQ(w->take_switch()->name, "spring");
}

// Staff copy only the manifest and leave it for longer than the settle time: the catalogue is
// refused, set aside in the inbox as spring.rejected with a note saying why, never current;
// copied again whole, it is installed.
TEST(CatalogueWatcher, HalfCopiedCatalogueIsNeverCurrent) {
    const fs::path root = fresh_dir("watch-half-slow");
    const CatalogueOptions o = options_for(root, 300ms);
    auto w = start(o);
    StderrCapture capture;
    write_text(o.inbox_dir / "spring" / "catalogue.toml", one_stone_manifest("spring"));
    ASSERT_TRUE(wait_until([&] { return w->counters().rejections == 1; }));
    const std::string why =
        "catalogue 'spring' rejected: stones/round.gemdb: cannot open: No such file";
    EXPECT_NE(capture.text().find(why), std::string::npos) << capture.text();
    EXPECT_NE(capture.text().find("; set aside as " + (o.inbox_dir / "spring.rejected").string()),
              std::string::npos)
        << capture.text();
    EXPECT_FALSE(fs::exists(o.inbox_dir / "spring"));
    EXPECT_TRUE(fs::exists(o.inbox_dir / "spring.rejected" / "catalogue.toml"));
    EXPECT_NE(read_text(o.inbox_dir / "spring.rejected.txt").find(why), std::string::npos);
    EXPECT_FALSE(fs::exists(o.state_dir / "current"));
    EXPECT_FALSE(w->take_switch().has_value());

    // A second refusal of the same name does not overwrite the first one's note, and neither
    // set-aside folder is looked at again.
    write_text(o.inbox_dir / "spring" / "catalogue.toml", one_stone_manifest("spring"));
    ASSERT_TRUE(wait_until([&] { return w->counters().rejections == 2; }));
    EXPECT_TRUE(fs::exists(o.inbox_dir / "spring-2.rejected.txt"));
    EXPECT_TRUE(fs::exists(o.inbox_dir / "spring.rejected.txt"));
    const auto scans = w->counters().scans;
    w->rescan();
    ASSERT_TRUE(wait_until([&] { return w->counters().scans > scans; }));
    EXPECT_EQ(w->counters().validations, 2u);

    write_catalogue(o.inbox_dir / "spring", "spring");
    ASSERT_TRUE(switch_signalled(*w));
    auto taken = w->take_switch();
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(read_bytes(taken->directory / "stones" / "round.gemdb"), read_bytes(tiny_database()));
}

// The same copy with every pause shorter than the settle time: the watcher waits for the
// whole and validates once. (The pauses are 100 ms against a 3 s settle time.)
TEST(CatalogueWatcher, CatalogueStillBeingCopiedIsNotLookedAt) {
    const fs::path root = fresh_dir("watch-half-fast");
    const CatalogueOptions o = options_for(root, 3000ms);
    auto w = start(o);
    write_text(o.inbox_dir / "spring" / "catalogue.toml", one_stone_manifest("spring"));
    const auto bytes = read_bytes(tiny_database());
    const fs::path database = o.inbox_dir / "spring" / "stones" / "round.gemdb";
    fs::create_directories(database.parent_path());
    {
        std::ofstream out(database, std::ios::binary);
        const std::size_t chunk = bytes.size() / 4 + 1;
        for (std::size_t at = 0; at < bytes.size(); at += chunk) {
            std::this_thread::sleep_for(100ms);
            out.write(reinterpret_cast<const char*>(bytes.data() + at),
                      static_cast<std::streamsize>(std::min(chunk, bytes.size() - at)));
            out.flush();
        }
    }
    ASSERT_TRUE(switch_signalled(*w));
    EXPECT_EQ(w->counters().validations, 1u);
    EXPECT_EQ(w->counters().rejections, 0u);
    auto taken = w->take_switch();
    ASSERT_TRUE(taken.has_value());
    EXPECT_EQ(read_bytes(taken->directory / "stones" / "round.gemdb"), bytes);
}

TEST(CatalogueWatcher, OldCopiesGoAndARestartDoesNotReinstall) {
    const fs::path root = fresh_dir("watch-prune");
    const CatalogueOptions o = options_for(root, 300ms);
    {
        auto w = start(o);
        for (const char* name : {"spring", "summer", "autumn"}) {
            ASSERT_FALSE(install_good(*w, o, name).empty()) << name;
        }
        EXPECT_EQ(entries(o.state_dir / "catalogues"),
                  (std::vector<std::string>{"autumn-3", "summer-2"}));
        EXPECT_EQ(fs::read_symlink(o.state_dir / "current"), fs::path("catalogues") / "autumn-3");
    }
    // The inbox still holds all three; a restarted kiosk keeps what is current.
    auto w = start(o);
    for (int i = 0; i < 2; ++i) {
        const auto scans = w->counters().scans;
        w->rescan();
        ASSERT_TRUE(wait_until([&] { return w->counters().scans > scans; }));
    }
    EXPECT_EQ(w->counters().validations, 0u);
    EXPECT_EQ(fs::read_symlink(o.state_dir / "current"), fs::path("catalogues") / "autumn-3");
}

// A full disk, made real in a child process by a file-size limit below the database's size
// (setrlimit(2) RLIMIT_FSIZE, SIGXFSZ ignored: write(2) fails with EFBIG).
TEST(CatalogueWatcher, CopyFailureOnAFullDiskKeepsTheCurrent) {
    const fs::path root = fresh_dir("watch-full");
    const CatalogueOptions o = options_for(root, 300ms);
    fs::path good;
    {
        auto w = start(o);
        good = install_good(*w, o, "spring");
    }
    ASSERT_FALSE(good.empty());
    // Written before the limit, under a hidden name the watcher ignores.
    write_catalogue(o.inbox_dir / ".summer", "summer");
    constexpr rlim_t kLimit = 16 * 1024;
    ASSERT_GT(fs::file_size(tiny_database()), kLimit);
    StderrCapture capture;
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{kLimit, kLimit};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(10);
        auto started = CatalogueWatcher::start(o);
        if (!started) ::_exit(11);
        CatalogueWatcher& w = *started.value();
        fs::rename(o.inbox_dir / ".summer", o.inbox_dir / "summer");
        if (!wait_until([&] { return w.counters().copy_failures == 1; })) ::_exit(12);
        if (w.take_switch().has_value() || w.counters().installs != 0) ::_exit(13);
        ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "10: setrlimit, 11: start, 12: no copy failure seen, "
                                         "13: something was installed";
    EXPECT_EQ(fs::canonical(o.state_dir / "current"), good);
    EXPECT_EQ(entries(o.state_dir / "catalogues"), std::vector<std::string>{"spring-1"})
        << "the partial copy must be removed";
    const std::string log = capture.text();
    EXPECT_NE(log.find("catalogue 'summer' not installed: copy failed: "), std::string::npos)
        << log;
    EXPECT_NE(log.find("round.gemdb: File too large"), std::string::npos) << log;
}

}  // namespace
}  // namespace gem::kiosk
