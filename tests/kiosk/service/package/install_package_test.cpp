// Installation (cmake --install into a staging folder) and the Debian package (cpack -G DEB)
// of this build folder. The expected paths are the ones the rest of the system fixes: the
// unit starts /usr/bin/gemkiosk with /etc/gemkiosk/gemkiosk.toml, systemd reads units from the
// folder its pkg-config file names (asked here with pkg-config itself; Debian's
// /lib/systemd/system without it), sysusers.d and tmpfiles.d files from /usr/lib.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "service/run_command.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using test::run_command;
using test::shell_quoted;

std::vector<std::string> programs() {
    std::vector<std::string> names;
    std::istringstream list(GEM_PROGRAMS);
    for (std::string name; list >> name;) names.push_back(name);
    return names;
}

std::string systemd_dir(const char* variable, const char* debian_default) {
    const test::CommandResult result =
        run_command(std::string("pkg-config --variable=") + variable + " systemd");
    std::string dir = result.output.substr(0, result.output.find('\n'));
    return result.status == 0 && !dir.empty() ? dir : debian_default;
}

// Paths below the root, without the leading slash, of every file the package must hold.
std::vector<std::string> expected_files() {
    const std::string units = systemd_dir("systemdsystemunitdir", "/lib/systemd/system").substr(1);
    std::vector<std::string> files = {
        "etc/gemkiosk/gemkiosk.toml",
        units + "/gemkiosk.service",
        units + "/gemkiosk-catalogue.path",
        units + "/gemkiosk-catalogue.service",
        systemd_dir("sysusersdir", "/usr/lib/sysusers.d").substr(1) + "/gemkiosk.conf",
        systemd_dir("tmpfilesdir", "/usr/lib/tmpfiles.d").substr(1) + "/gemkiosk.conf",
    };
    for (const std::string& program : programs()) files.push_back("usr/bin/" + program);
    if (fs::exists(fs::path(GEM_BINARY_DIR) / "catalogue/catalogue.toml")) {
        files.push_back("usr/share/gemkiosk/catalogue/catalogue.toml");
    }
    return files;
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

class Package : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "gemkiosk-package-XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(Package, InstallsIntoAStagingFolder) {
    ASSERT_FALSE(programs().empty());
    const fs::path stage = dir_ / "stage";
    const test::CommandResult result = run_command("DESTDIR=" + shell_quoted(stage.string()) +
                                                   " " GEM_CMAKE_COMMAND " --install " +
                                                   shell_quoted(GEM_BINARY_DIR) + " --prefix /usr");
    ASSERT_EQ(result.status, 0) << result.output;
    for (const std::string& file : expected_files()) {
        EXPECT_TRUE(fs::is_regular_file(stage / file)) << file << "\n" << result.output;
    }
    for (const std::string& program : programs()) {
        EXPECT_EQ(::access((stage / "usr/bin" / program).c_str(), X_OK), 0) << program;
    }
    // The units and the config are the files of the source tree, unchanged.
    const std::string units = systemd_dir("systemdsystemunitdir", "/lib/systemd/system").substr(1);
    EXPECT_EQ(read_text(stage / units / "gemkiosk.service"),
              read_text(fs::path(GEM_SOURCE_DIR) / "systemd/gemkiosk.service"));
    EXPECT_EQ(read_text(stage / "etc/gemkiosk/gemkiosk.toml"),
              read_text(fs::path(GEM_SOURCE_DIR) / "config/gemkiosk.toml"));
    // Nothing lands outside the staging folder's usr, etc and lib.
    for (const auto& entry : fs::directory_iterator(stage)) {
        const std::string name = entry.path().filename().string();
        EXPECT_TRUE(name == "usr" || name == "etc" || name == "lib") << name;
    }
}

TEST_F(Package, BuildsADebianPackage) {
    const test::CommandResult packed = run_command(
        "cd " + shell_quoted(dir_.string()) + " && " GEM_CPACK_COMMAND " -G DEB --config " +
        shell_quoted(std::string(GEM_BINARY_DIR) + "/CPackConfig.cmake") + " -B " +
        shell_quoted(dir_.string()));
    ASSERT_EQ(packed.status, 0) << packed.output;
    fs::path deb;
    for (const auto& entry : fs::directory_iterator(dir_)) {
        if (entry.path().extension() == ".deb") deb = entry.path();
    }
    ASSERT_FALSE(deb.empty()) << packed.output;
    EXPECT_EQ(deb.filename().string().rfind("gemkiosk_", 0), 0u) << deb;

    const test::CommandResult contents = run_command("dpkg-deb -c " + shell_quoted(deb.string()));
    ASSERT_EQ(contents.status, 0) << contents.output;
    for (const std::string& file : expected_files()) {
        EXPECT_NE(contents.output.find(" ./" + file + "\n"), std::string::npos) << file << "\n"
                                                                                << contents.output;
    }

    const test::CommandResult fields = run_command("dpkg-deb -f " + shell_quoted(deb.string()) +
                                                   " Package Section Depends Maintainer");
    ASSERT_EQ(fields.status, 0) << fields.output;
    EXPECT_NE(fields.output.find("Package: gemkiosk\n"), std::string::npos) << fields.output;
    EXPECT_NE(fields.output.find("Section: misc\n"), std::string::npos) << fields.output;
    EXPECT_NE(fields.output.find("systemd"), std::string::npos) << fields.output;
    // dpkg-shlibdeps found the C++ runtime the programs link against.
    EXPECT_NE(fields.output.find("libstdc++6"), std::string::npos) << fields.output;

    const fs::path control = dir_ / "control";
    ASSERT_EQ(run_command("dpkg-deb -e " + shell_quoted(deb.string()) + " " +
                          shell_quoted(control.string()))
                  .status,
              0);
    for (const char* script : {"postinst", "prerm", "postrm"}) {
        EXPECT_EQ(::access((control / script).c_str(), X_OK), 0) << script;
    }
    EXPECT_NE(read_text(control / "postinst").find("systemd-sysusers"), std::string::npos);
    EXPECT_NE(read_text(control / "conffiles").find("/etc/gemkiosk/gemkiosk.toml"),
              std::string::npos);
}

}  // namespace
}  // namespace gem::kiosk
