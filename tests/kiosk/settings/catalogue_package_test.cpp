// gemtables package: a sealed catalogue as a Debian package, read back with dpkg-deb (Debian's
// own tool, not the code that wrote it): its control fields, its files where the kiosk watches
// for them, the catalogue it unpacks still signed and whole, and a maintainer script that only
// asks the kiosk to look. A catalogue the kiosk would refuse is not packaged.

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "catalogue/catalogue_signature.hpp"
#include "catalogue/validate.hpp"
#include "catalogue_test_support.hpp"
#include "commands.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using namespace catalogue_test;

fs::path sealed_and_signed(const fs::path& root, fs::path* pub) {
    const fs::path dir = root / "spring";
    write_catalogue(dir, "Spring 2027");
    *pub = root / "chain.pub";
    int status = -1;
    std::string out = run_command(
        "minisign -G -W -p '" + pub->string() + "' -s '" + (root / "chain.key").string() + "'",
        &status);
    EXPECT_EQ(status, 0) << out;
    tables::SealOptions seal{dir.string(), (root / "chain.key").string()};
    EXPECT_EQ(tables::run_seal(seal), 0);
    EXPECT_TRUE(fs::exists(dir / "catalogue.toml.minisig"));
    return dir;
}

TEST(CataloguePackage, InstallsTheSignedCatalogueWhereTheKioskWatches) {
    const fs::path root = fresh_dir("package-good");
    fs::path pub;
    const fs::path dir = sealed_and_signed(root, &pub);
    tables::PackageOptions o;
    o.catalogue_dir = dir.string();
    o.version = "2027.1";
    ASSERT_EQ(tables::run_package(o), 0);
    const fs::path deb = root / "gemkiosk-catalogue-spring-2027_2027.1_all.deb";
    ASSERT_TRUE(fs::exists(deb));

    int status = -1;
    const std::string fields = run_command(
        "dpkg-deb -f '" + deb.string() + "' Package Version Architecture Enhances", &status);
    ASSERT_EQ(status, 0) << fields;
    EXPECT_EQ(fields,
              "Package: gemkiosk-catalogue-spring-2027\nVersion: 2027.1\nArchitecture: all\n"
              "Enhances: gemkiosk\n");
    const std::string listing = run_command("dpkg-deb -c '" + deb.string() + "'", &status);
    ASSERT_EQ(status, 0) << listing;
    for (const char* file : {"catalogue.toml", "catalogue.toml.minisig", "stones/round.gemdb"}) {
        EXPECT_NE(listing.find(" ./usr/share/gemkiosk/catalogues/gemkiosk-catalogue-spring-2027/" +
                               std::string(file) + "\n"),
                  std::string::npos)
            << listing;
    }
    EXPECT_NE(listing.find("root/root"), std::string::npos) << listing;

    // Unpacked by dpkg-deb, the catalogue is the signed one.
    const fs::path unpacked = root / "unpacked";
    run_command("dpkg-deb -x '" + deb.string() + "' '" + unpacked.string() + "'", &status);
    ASSERT_EQ(status, 0);
    std::vector<std::string> problems;
    Result<Catalogue> shown = validate_catalogue(
        unpacked / "usr/share/gemkiosk/catalogues/gemkiosk-catalogue-spring-2027",
        parse_trust(true, {{pub.string(), read_text(pub)}}, problems));
    ASSERT_TRUE(shown.ok()) << shown.error();
    EXPECT_EQ(shown.value().name, "Spring 2027");
    EXPECT_FALSE(shown.value().signed_by.empty());

    // The maintainer script asks a running kiosk to look, and never restarts it.
    const fs::path control = root / "control";
    run_command("dpkg-deb -e '" + deb.string() + "' '" + control.string() + "'", &status);
    ASSERT_EQ(status, 0);
    const std::string postinst = read_text(control / "postinst");
    EXPECT_NE(postinst.find("systemctl kill --kill-whom=main --signal=SIGHUP gemkiosk.service"),
              std::string::npos);
    EXPECT_EQ(postinst.find("reload"), std::string::npos)
        << "ExecReload would run in the kiosk's unit, with its PAM session and its TTY";
    std::istringstream lines(postinst);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind('#', 0) == 0) continue;
        EXPECT_EQ(line.find("restart"), std::string::npos) << line;
        EXPECT_EQ(line.find("stop"), std::string::npos) << line;
    }
    EXPECT_EQ(run_command("sh -n '" + (control / "postinst").string() + "'", &status), "");
    EXPECT_EQ(status, 0);
    EXPECT_FALSE(fs::exists(control / "prerm"));
    EXPECT_FALSE(fs::exists(control / "postrm"));
}

TEST(CataloguePackage, WhatTheKioskWouldRefuseIsNotPackaged) {
    const fs::path root = fresh_dir("package-refused");
    fs::path pub;
    const fs::path dir = sealed_and_signed(root, &pub);
    write_text(dir / "notes.txt", "added after sealing");
    tables::PackageOptions o;
    o.catalogue_dir = dir.string();
    o.version = "1";
    EXPECT_NE(tables::run_package(o), 0);
    fs::remove(dir / "notes.txt");
    o.version = "first";
    EXPECT_NE(tables::run_package(o), 0) << "a Debian version starts with a digit";
    o.version = "1";
    o.package = "Spring_Catalogue";
    EXPECT_NE(tables::run_package(o), 0) << "a Debian package name is lower case";
    for (const auto& entry : fs::directory_iterator(root)) {
        EXPECT_NE(entry.path().extension(), ".deb") << entry.path();
    }
}

}  // namespace
}  // namespace gem::kiosk
