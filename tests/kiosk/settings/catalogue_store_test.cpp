// The state directory: copies are complete or absent (a file-size limit makes a real EFBIG
// mid-copy), state/current always resolves to a complete copy while it is switched, old copies
// go, and the kiosk starts from state/current or else the shipped default.

#include <gtest/gtest.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <thread>

#include "catalogue/catalogue_completion.hpp"
#include "catalogue/catalogue_store.hpp"
#include "catalogue/validate.hpp"
#include "catalogue_test_support.hpp"
#include "commands.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using namespace catalogue_test;

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(CatalogueStore, CopyIsByteIdenticalAndNumbered) {
    const fs::path root = fresh_dir("store-copy");
    write_catalogue(root / "source", "spring");
    auto first = copy_catalogue(root / "source", root / "state", "spring");
    ASSERT_TRUE(first.ok()) << first.error();
    EXPECT_EQ(first.value(), root / "state" / "catalogues" / "spring-1");
    EXPECT_EQ(read_bytes(first.value() / "stones" / "round.gemdb"), read_bytes(tiny_database()));
    EXPECT_EQ(read_bytes(first.value() / "catalogue.toml"),
              read_bytes(root / "source" / "catalogue.toml"));
    // A name that could make a path or a hidden entry is made plain: ".." and "/" go.
    auto second = copy_catalogue(root / "source", root / "state", "../evil name");
    ASSERT_TRUE(second.ok()) << second.error();
    EXPECT_EQ(second.value(), root / "state" / "catalogues" / "_evil_name-2");
    EXPECT_EQ(entries(root / "state" / "catalogues"),
              (std::vector<std::string>{"_evil_name-2", "spring-1"}));
}

TEST(CatalogueStore, SymlinkInsideASourceIsRefusedAndLeavesNothing) {
    const fs::path root = fresh_dir("store-symlink");
    write_catalogue(root / "source", "spring");
    fs::create_symlink("/etc/passwd", root / "source" / "stones" / "link");
    auto copy = copy_catalogue(root / "source", root / "state", "spring");
    ASSERT_FALSE(copy.ok());
    EXPECT_EQ(copy.error(),
              (root / "source" / "stones" / "link").string() + ": not a regular file or directory");
    EXPECT_TRUE(entries(root / "state" / "catalogues").empty());
}

// The child process gets a file-size limit below the database's size, as a nearly full disk
// would stop it (setrlimit(2) RLIMIT_FSIZE; with SIGXFSZ ignored, write(2) fails with EFBIG).
TEST(CatalogueStore, CopyFailingMidFileRemovesThePartialCopy) {
    const fs::path root = fresh_dir("store-full");
    write_catalogue(root / "source", "spring");
    auto kept = copy_catalogue(root / "source", root / "state", "spring");
    ASSERT_TRUE(kept.ok()) << "without the limit the copy works: " << kept.error();
    ASSERT_TRUE(make_current(root / "state", kept.value()).ok());
    constexpr rlim_t kLimit = 16 * 1024;
    ASSERT_GT(fs::file_size(tiny_database()), kLimit);
    ASSERT_LT(fs::file_size(root / "source" / "catalogue.toml"), kLimit);

    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{kLimit, kLimit};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(10);
        auto copy = copy_catalogue(root / "source", root / "state", "spring");
        if (copy.ok()) ::_exit(11);
        const std::string expected = "round.gemdb: File too large";
        if (copy.error().find(expected) == std::string::npos) ::_exit(12);
        ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "10: setrlimit failed, 11: copy succeeded, 12: error "
                                         "did not name the file and EFBIG";
    EXPECT_EQ(entries(root / "state" / "catalogues"), std::vector<std::string>{"spring-1"})
        << "the partial copy (temporary or renamed) must be gone";
    EXPECT_EQ(current_copy(root / "state"), fs::canonical(kept.value()));
}

TEST(CatalogueStore, CurrentAlwaysResolvesToACompleteCopyWhileSwitching) {
    const fs::path root = fresh_dir("store-switch");
    write_catalogue(root / "source", "spring");
    const fs::path state = root / "state";
    auto a = copy_catalogue(root / "source", state, "a");
    auto b = copy_catalogue(root / "source", state, "b");
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_TRUE(make_current(state, a.value()).ok());
    const auto database_size = fs::file_size(tiny_database());

    std::atomic<bool> done{false};
    std::atomic<int> looks{0}, broken{0};
    std::thread reader([&] {
        while (!done) {
            std::error_code ec;
            // What a kiosk starting at this moment would open.
            const auto size = fs::file_size(state / "current" / "stones" / "round.gemdb", ec);
            if (ec || size != database_size) ++broken;
            ++looks;
        }
    });
    for (int i = 0; i < 200; ++i) {
        ASSERT_TRUE(make_current(state, (i % 2 ? a : b).value()).ok());
    }
    done = true;
    reader.join();
    EXPECT_GT(looks.load(), 0);
    EXPECT_EQ(broken.load(), 0) << "state/current was missing or incomplete " << broken
                                << " times of " << looks;
    EXPECT_EQ(fs::read_symlink(state / "current"), fs::path("catalogues") / "a-1");
    EXPECT_FALSE(fs::exists(fs::symlink_status(state / ".current.tmp")));
}

TEST(CatalogueStore, PruneKeepsCurrentAndPrevious) {
    const fs::path root = fresh_dir("store-prune");
    write_catalogue(root / "source", "x");
    const fs::path state = root / "state";
    std::vector<fs::path> copies;
    for (int i = 0; i < 4; ++i)
        copies.push_back(copy_catalogue(root / "source", state, "x").value());
    fs::create_directory(state / "catalogues" / ".tmp-x-9");  // an interrupted copy
    prune_copies(state, {fs::canonical(copies[3]), fs::canonical(copies[2])});
    EXPECT_EQ(entries(state / "catalogues"), (std::vector<std::string>{"x-3", "x-4"}));
}

TEST(CatalogueStore, RemembersInstalledSources) {
    const fs::path state = fresh_dir("store-sources");
    EXPECT_TRUE(read_sources(state, kInstalledSources).empty());
    ASSERT_TRUE(remember_source(state, kInstalledSources, 0x0123456789abcdefull).ok());
    ASSERT_TRUE(remember_source(state, kInstalledSources, 42).ok());
    EXPECT_EQ(read_sources(state, kInstalledSources),
              (std::vector<std::uint64_t>{0x0123456789abcdefull, 42}));
}

// Options for a kiosk under `root` whose shipped catalogue is "shipped".
CatalogueOptions startup_options(const fs::path& root) {
    CatalogueOptions options;
    options.state_dir = root / "state";
    options.default_catalogue = root / "default";
    write_catalogue(root / "default", "shipped");
    return options;
}

TEST(CatalogueStore, StartsFromCurrentElseTheDefault) {
    const fs::path root = fresh_dir("store-startup");
    const CatalogueOptions options = startup_options(root);
    {
        auto loaded = load_startup_catalogue(options);
        ASSERT_TRUE(loaded.ok()) << loaded.error();
        EXPECT_EQ(loaded.value().name, "shipped");
    }
    write_catalogue(root / "installed", "spring");
    auto copy = copy_catalogue(root / "installed", options.state_dir, "spring");
    ASSERT_TRUE(copy.ok());
    ASSERT_TRUE(make_current(options.state_dir, copy.value()).ok());
    {
        auto loaded = load_startup_catalogue(options);
        ASSERT_TRUE(loaded.ok()) << loaded.error();
        EXPECT_EQ(loaded.value().name, "spring");
        EXPECT_EQ(loaded.value().directory, fs::canonical(copy.value()));
    }
    // A damaged installed copy: the default, and a warning naming the fault.
    fs::resize_file(copy.value() / "stones" / "round.gemdb", 100);
    StderrCapture capture;
    auto loaded = load_startup_catalogue(options);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(loaded.value().name, "shipped");
    EXPECT_NE(capture.text().find("catalogue 'spring' rejected: stones/round.gemdb: truncated"),
              std::string::npos)
        << capture.text();
    // Neither usable: one error saying why.
    fs::remove(root / "default" / "catalogue.toml");
    auto none = load_startup_catalogue(options);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().find("truncated"), std::string::npos) << none.error();
    EXPECT_NE(none.error().find("catalogue.toml"), std::string::npos) << none.error();
}

// At start the installed copy is opened for its first stone; CatalogueCompletion validates it
// whole while that stone is shown and hands the whole catalogue over; where a later entry is
// damaged, it hands the shipped default instead, and the warning says why.
TEST(CatalogueStore, TheStartupCatalogueIsCompletedInTheBackground) {
    const fs::path root = fresh_dir("store-completion");
    const CatalogueOptions options = startup_options(root);
    write_text(root / "installed" / "catalogue.toml", R"([catalogue]
name = "spring"
[[stone]]
name = "Round"
database = "stones/round.gemdb"
[[stone]]
name = "Second"
database = "stones/second.gemdb"
)");
    write_bytes(root / "installed" / "stones" / "round.gemdb", read_bytes(tiny_database()));
    write_bytes(root / "installed" / "stones" / "second.gemdb", read_bytes(tiny_database()));
    auto copy = copy_catalogue(root / "installed", options.state_dir, "spring");
    ASSERT_TRUE(copy.ok());
    ASSERT_TRUE(make_current(options.state_dir, copy.value()).ok());
    const auto complete = [&] {
        auto completion = CatalogueCompletion::start(options);
        EXPECT_TRUE(completion.ok()) << completion.error();
        std::optional<Result<Catalogue>> whole;
        EXPECT_TRUE(wait_until([&] {
            struct pollfd p {
                completion.value()->event_fd(), POLLIN, 0
            };
            if (::poll(&p, 1, 0) == 1) whole = completion.value()->take();
            return whole.has_value();
        }));
        return whole.value_or(Error{"never completed"});
    };
    auto first = load_startup_catalogue(options, Entries::first);
    ASSERT_TRUE(first.ok()) << first.error();
    EXPECT_EQ(first.value().name, "spring");
    EXPECT_EQ(first.value().stones.size(), 1u);
    EXPECT_EQ(first.value().unchecked, 1u);
    {
        auto whole = complete();
        ASSERT_TRUE(whole.ok()) << whole.error();
        EXPECT_EQ(whole.value().directory, first.value().directory);
        EXPECT_EQ(whole.value().stones.size(), 2u);
    }
    fs::resize_file(copy.value() / "stones" / "second.gemdb", 100);
    first = load_startup_catalogue(options, Entries::first);
    ASSERT_TRUE(first.ok()) << first.error();
    EXPECT_EQ(first.value().name, "spring");  // its first stone is intact
    StderrCapture capture;
    auto whole = complete();
    ASSERT_TRUE(whole.ok()) << whole.error();
    EXPECT_EQ(whole.value().name, "shipped");
    EXPECT_NE(capture.text().find("catalogue 'spring' rejected: stones/second.gemdb: truncated"),
              std::string::npos)
        << capture.text();
}

// The installed copy is not hashed again at start (it was when installed): a file whose digest
// no longer matches, but that still reads, is shown; the same copy delivered again is refused
// for it. Its databases' own checksums still find damage (above).
TEST(CatalogueStore, TheInstalledCopyIsNotHashedAgainAtStart) {
    const fs::path root = fresh_dir("store-startup-digests");
    const CatalogueOptions options = startup_options(root);
    write_catalogue(root / "installed", "spring");
    write_text(root / "installed" / "notes.txt", "made in spring");
    ASSERT_EQ(tables::run_seal({(root / "installed").string(), ""}), 0);
    auto copy = copy_catalogue(root / "installed", options.state_dir, "spring");
    ASSERT_TRUE(copy.ok());
    ASSERT_TRUE(make_current(options.state_dir, copy.value()).ok());
    write_text(copy.value() / "notes.txt", "made in summer");
    auto loaded = load_startup_catalogue(options);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(loaded.value().name, "spring");
    const Result<Catalogue> delivered = validate_catalogue(copy.value());
    ASSERT_FALSE(delivered.ok());
    EXPECT_NE(delivered.error().find("notes.txt: does not match its digest"), std::string::npos)
        << delivered.error();
}

}  // namespace
}  // namespace gem::kiosk
