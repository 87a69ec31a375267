// The fingerprint a catalogue source is remembered by: the same for a tree left alone and
// read, different for any change a copy or a package manager makes, including dpkg putting
// back a file with the same name, size and modification time (a downgrade to a version shown
// before).

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "catalogue/directory_fingerprint.hpp"
#include "catalogue_test_support.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using namespace catalogue_test;

std::uint64_t fingerprint(const fs::path& dir) {
    Result<DirectoryFingerprint> f = fingerprint_directory(dir);
    EXPECT_TRUE(f.ok()) << (f.ok() ? "" : f.error());
    return f.ok() ? f.value().hash : 0;
}

TEST(DirectoryFingerprint, ReadingLeavesItAndReplacingAFileAsDpkgDoesChangesIt) {
    const fs::path dir = fresh_dir("fingerprint");
    write_text(dir / "catalogue.toml", "[catalogue]\nname = \"a\"\n");
    write_text(dir / "stones" / "a.toml", "one");
    const std::uint64_t first = fingerprint(dir);
    EXPECT_EQ(read_text(dir / "stones" / "a.toml"), "one");
    EXPECT_EQ(fingerprint(dir), first) << "reading a file is no change";

    // dpkg unpacks to a temporary name, gives the file the package's modification time and
    // renames it over the old one: same name, size and mtime.
    struct stat before {};
    ASSERT_EQ(::stat((dir / "stones" / "a.toml").c_str(), &before), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    write_text(dir / "stones" / "a.toml.dpkg-new", "one");
    const timespec times[2] = {before.st_atim, before.st_mtim};
    ASSERT_EQ(::utimensat(AT_FDCWD, (dir / "stones" / "a.toml.dpkg-new").c_str(), times, 0), 0);
    EXPECT_NE(fingerprint(dir), first) << "a new file is a change";
    fs::rename(dir / "stones" / "a.toml.dpkg-new", dir / "stones" / "a.toml");
    struct stat after {};
    ASSERT_EQ(::stat((dir / "stones" / "a.toml").c_str(), &after), 0);
    ASSERT_EQ(after.st_mtim.tv_nsec, before.st_mtim.tv_nsec);
    ASSERT_EQ(after.st_size, before.st_size);
    EXPECT_NE(fingerprint(dir), first) << "the same file put back is a change";
}

}  // namespace
}  // namespace gem::kiosk
