#pragma once
// The gemtables subcommands, each a function from its parsed options to an exit status.
// They print their result on stdout and one clear message on stderr when something is wrong.

#include <cstdint>
#include <string>
#include <vector>

namespace gem::tables {

struct BuildOptions {
    std::string stone_file;
    std::string out;
    // > 0: the stone scaled to this girdle width first, as a piece sizes it (piece tables).
    double width_mm = 0.0;
    std::vector<std::uint32_t> levels{128, 256, 512};
    double spacing_deg = 5.0;  // the thesis stored a table every 0.1 rad (5.7°)
    double min_elevation_deg = -10.0;
    std::uint32_t depth = 12;
    double threshold = 1e-4;
    bool dispersion = false;
    unsigned jobs = 0;  // 0: every core
    // > 0: levels, spacing, depth, threshold and dispersion are chosen under this error
    // budget for a stone screen_px across (budget.hpp) instead of taken from the options.
    double budget_delta_e = 0.0;
    int screen_px = 0;
    double max_jump_px = 8.0;
    bool choose_only = false;  // print the choice, build nothing
    // For a build beside a live display (process_limits.hpp): idle CPU priority, and at most
    // this much address space (0: no limit).
    bool idle = false;
    std::uint64_t memory_mb = 0;
};

// gemtables package: a catalogue folder as a Debian package that installs it in
// /usr/share/gemkiosk/catalogues/<package>/, where the kiosk takes it from.
struct PackageOptions {
    std::string catalogue_dir;
    std::string version;  // Debian version, e.g. "2027.1"
    std::string package;  // empty: gemkiosk-catalogue-<the catalogue's name>
    std::string out_dir;  // empty: beside the catalogue folder
    std::string maintainer = "gemkiosk catalogue <root@localhost>";
};

// gemtables seal: writes the manifest's [blake2b] table, then signs it with minisign when a
// secret key is given.
struct SealOptions {
    std::string catalogue_dir;
    std::string secret_key;  // minisign's secret key file; empty: not signed
};

struct CatalogueOptions {
    std::string designs_dir;  // stone descriptions (.toml) and models (.asc, .obj, .stl)
    std::string out;          // the catalogue folder to write
    std::string name = "designs";
    std::string material = "diamond";  // for model files (a .toml names its own)
    BuildOptions build;                // the tables of stones that need them
    std::string secret_key;            // sign with minisign (gemtables seal)
    PackageOptions deb;                // a version: also package it (gemtables package)
};

struct VerifyOptions {
    std::string database;
    std::uint32_t samples = 2000;
    std::uint64_t seed = 1;
};

struct InspectOptions {
    std::string database;
    double azimuth_deg = 0.0;
    double elevation_deg = 90.0;
    int level = -1;  // -1: the finest
    std::string prefix;
};

int run_build(const BuildOptions& options);
int run_catalogue(const CatalogueOptions& options);
int run_seal(const SealOptions& options);
int run_package(const PackageOptions& options);
int run_info(const std::string& database);
// gemtables piece: a piece (.toml, .glb, .gltf) written as a .glb.
int run_piece(const std::string& piece_file, const std::string& out);
// gemtables piece FILE --check: the piece read as the kiosk reads it, and what the reader said
// (each stone with its evidence, each repair and warning, the metal) with the load time; exit
// status 1 when it is refused.
int run_piece_check(const std::string& piece_file);
int run_verify(const VerifyOptions& options);
int run_inspect(const InspectOptions& options);

// "gemtables: <message>" on stderr; returns the failure exit status.
int fail(const std::string& message);

}  // namespace gem::tables
