// gemtables package: a catalogue folder as a Debian package, so that a chain delivers it with
// its own apt repository (docs/operating.md, "A chain's catalogues"). The package installs the
// folder in /usr/share/gemkiosk/catalogues/<package>/, which the kiosk watches; dpkg unpacks
// a new version's files beside the old ones and renames them into place, and the kiosk checks
// the signed digests of the whole folder before it copies it, so a half-unpacked folder (a
// power cut during an upgrade) is refused and the catalogue on screen stays. The maintainer
// script only asks a running kiosk to look (SIGHUP through systemctl kill); it never restarts it,
// so a shopper's view is never cut. Built with dpkg-deb, which every Debian system has.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <system_error>

#include <toml++/toml.h>

#include "commands.hpp"
#include "delivery/catalogue_files.hpp"
#include "run_program.hpp"
#include "util/atomic_file.hpp"

namespace gem::tables {

namespace {

namespace fs = std::filesystem;

constexpr const char* kPackagesDir = "usr/share/gemkiosk/catalogues";

constexpr const char* kPostinst = R"(#!/bin/sh
# A new catalogue is in /usr/share/gemkiosk/catalogues: ask a running kiosk to look now
# (SIGHUP to its main process; it switches between two frames). Never a restart: the
# kiosk may be showing a shopper a ring.
set -e
if [ "$1" = configure ] && command -v systemctl >/dev/null 2>&1; then
    if systemctl --quiet is-active gemkiosk.service; then
        systemctl kill --kill-whom=main --signal=SIGHUP gemkiosk.service || true
    fi
fi
exit 0
)";

// Debian policy 5.6.1: lower case letters, digits, '+', '-', '.'; at least two; first
// alphanumeric.
bool valid_package_name(const std::string& name) {
    if (name.size() < 2 || !std::isalnum(static_cast<unsigned char>(name[0]))) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
    });
}

// Debian policy 5.6.12, without an epoch: starts with a digit; letters, digits, . + ~ -.
bool valid_version(const std::string& version) {
    if (version.empty() || !std::isdigit(static_cast<unsigned char>(version[0]))) return false;
    return std::all_of(version.begin(), version.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '~' ||
               c == '-';
    });
}

std::string package_name_for(const std::string& catalogue) {
    std::string out = "gemkiosk-catalogue-";
    for (const char c : catalogue) {
        const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const bool plain = (lower >= 'a' && lower <= 'z') || (lower >= '0' && lower <= '9');
        if (plain) {
            out += lower;
        } else if (out.back() != '-') {
            out += '-';
        }
    }
    while (out.back() == '-') out.pop_back();
    return out;
}

bool write_text(const fs::path& path, const std::string& text, fs::perms perms,
                std::string& error) {
    auto written = write_file_atomic(path, text.data(), text.size());
    if (!written) {
        error = written.error();
        return false;
    }
    std::error_code ec;
    fs::permissions(path, perms, ec);
    if (ec) error = path.string() + ": " + ec.message();
    return !ec;
}

}  // namespace

int run_package(const PackageOptions& o) {
    const fs::path dir = fs::absolute(o.catalogue_dir).lexically_normal();
    std::string name;
    std::map<std::string, std::string> digests;
    try {
        const toml::table manifest = toml::parse_file((dir / kManifestName).string());
        name = manifest["catalogue"]["name"].value_or(std::string());
        if (const toml::table* table = manifest["blake2b"].as_table()) {
            for (auto&& [file, digest] : *table) {
                digests[std::string(file.str())] = digest.value_or(std::string());
            }
        }
    } catch (const toml::parse_error& err) {
        return fail((dir / kManifestName).string() + ": " + std::string(err.description()));
    }
    if (name.empty()) return fail((dir / kManifestName).string() + ": no [catalogue] name");
    const std::string package = o.package.empty() ? package_name_for(name) : o.package;
    if (!valid_package_name(package)) {
        return fail("--package '" + package +
                    "': a Debian package name is lower case letters, digits, '+', '-' and '.'");
    }
    if (!valid_version(o.version)) {
        return fail("--version '" + o.version +
                    "': a Debian version starts with a digit and holds letters, digits, . + ~ -");
    }
    // What the kiosk would refuse is not packaged: every file named with its digest, and the
    // digests right (a signature, if any, is the kiosk's to check against its keys).
    if (digests.empty()) {
        return fail((dir / kManifestName).string() +
                    ": names no file's digest: run gemtables seal first");
    }
    if (Result<bool> whole = check_catalogue_digests(dir, digests); !whole) {
        return fail(dir.string() + ": " + whole.error() + " (gemtables seal writes them anew)");
    }
    std::error_code ec;
    if (!fs::exists(dir / kSignatureName, ec)) {
        std::printf(
            "gemtables: note: %s is not signed; kiosks that list trusted keys will "
            "refuse it (gemtables seal --sign)\n",
            dir.c_str());
    }

    const fs::path out_dir = o.out_dir.empty() ? dir.parent_path() : fs::path(o.out_dir);
    const fs::path deb = out_dir / (package + "_" + o.version + "_all.deb");
    const fs::path stage = out_dir / ("." + package + "_" + o.version + ".stage");
    fs::remove_all(stage, ec);
    const fs::path target = stage / kPackagesDir / package;
    fs::create_directories(target.parent_path(), ec);
    if (!ec) fs::copy(dir, target, fs::copy_options::recursive, ec);
    if (!ec) fs::create_directories(stage / "DEBIAN", ec);
    if (ec) {
        fs::remove_all(stage, ec);
        return fail(stage.string() + ": cannot stage the package: " + ec.message());
    }
    std::uintmax_t bytes = 0;
    for (const auto& entry : fs::recursive_directory_iterator(target, ec)) {
        std::error_code e;
        const fs::perms perms = entry.is_directory(e) ? fs::perms(0755) : fs::perms(0644);
        fs::permissions(entry.path(), perms, e);
        if (entry.is_regular_file(e)) bytes += entry.file_size(e);
    }
    for (fs::path p = target; p != stage; p = p.parent_path()) {
        fs::permissions(p, fs::perms(0755), ec);
    }
    const std::string control =
        "Package: " + package + "\nVersion: " + o.version +
        "\nArchitecture: all\nMaintainer: " + o.maintainer +
        "\nInstalled-Size: " + std::to_string((bytes + 1023) / 1024) +
        "\nSection: misc\nPriority: optional\nEnhances: gemkiosk\nDescription: gemkiosk "
        "catalogue '" +
        name + "'\n A catalogue for the gemkiosk store display, installed in\n /" + kPackagesDir +
        "/" + package +
        ".\n A kiosk shows it once it has checked its signature against the\n keys it trusts.\n";
    std::string error;
    if (!write_text(stage / "DEBIAN" / "control", control, fs::perms(0644), error) ||
        !write_text(stage / "DEBIAN" / "postinst", kPostinst, fs::perms(0755), error)) {
        fs::remove_all(stage, ec);
        return fail(error);
    }
    fs::permissions(stage / "DEBIAN", fs::perms(0755), ec);
    fs::permissions(stage, fs::perms(0755), ec);
    const int built = run_program(
        {"dpkg-deb", "--root-owner-group", "-Zxz", "--build", stage.string(), deb.string()});
    fs::remove_all(stage, ec);
    if (built != 0) return fail(deb.string() + ": dpkg-deb could not build it");
    std::printf("gemtables: wrote %s (installs /%s/%s)\n", deb.c_str(), kPackagesDir,
                package.c_str());
    return 0;
}

}  // namespace gem::tables
