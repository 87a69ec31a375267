// gemtables: the pre-computation stage. Builds a stone's ray-table database, and checks,
// describes and pictures existing ones; writes pieces as glTF. A thin main: the work is in the
// engine and the command files beside this one.
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"

namespace {

// Sides must ascend: the cache shows a coarser level while a finer one decodes.
std::string check_levels(const std::vector<std::uint32_t>& levels) {
    for (std::size_t i = 0; i < levels.size(); ++i) {
        if (levels[i] < 1 || levels[i] > 8192) return "sides must lie in 1 .. 8192";
        if (i > 0 && levels[i] <= levels[i - 1]) return "sides must ascend, e.g. 128,256,512";
    }
    if (levels.empty() || levels.size() > 16) return "give 1 to 16 sides";
    return {};
}

}  // namespace

int main(int argc, char** argv) {
    using namespace gem::tables;
    CLI::App app{
        "gemtables: builds, verifies, describes and pictures gemstone ray-table "
        "databases (.gemdb)."};
    app.require_subcommand(1);

    BuildOptions build;
    CLI::App* b = app.add_subcommand("build", "trace every stored view of a stone into a database");
    b->add_option("stone", build.stone_file, "stone description (TOML, config/stones/README.md)")
        ->required();
    b->add_option("-o,--out", build.out, "database to write (.gemdb)")->required();
    b->add_option("--width-mm", build.width_mm,
                  "scale the stone to this girdle width first, as a piece's width_mm does (a "
                  "piece's stone drawn from tables)")
        ->check(CLI::Range(0.1, 100.0));
    b->add_option("--levels", build.levels, "image sides per view, ascending")
        ->delimiter(',')
        ->capture_default_str();
    b->add_option("--spacing", build.spacing_deg, "angle between stored views (degrees)")
        ->check(CLI::Range(0.05, 90.0))
        ->capture_default_str();
    b->add_option("--min-elevation", build.min_elevation_deg,
                  "lowest view elevation stored (degrees; -90 = whole sphere)")
        ->check(CLI::Range(-90.0, 89.0))
        ->capture_default_str();
    b->add_option("--depth", build.depth, "internal ray segments followed")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    b->add_option("--threshold", build.threshold, "exit rays lighter than this are dropped")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    CLI::Option* dispersion =
        b->add_flag("--dispersion", build.dispersion, "store d(direction)/dn per exit ray (fire)");
    CLI::Option* budget =
        b->add_option("--budget", build.budget_delta_e,
                      "choose spacing, level, depth, threshold and dispersion: the cheapest that "
                      "keep the mean CIEDE2000 over the stone within this (measured on pilot "
                      "views; needs --screen)")
            ->check(CLI::Range(0.01, 100.0));
    b->add_option("--screen", build.screen_px,
                  "with --budget: pixels across the stone's bounding sphere on screen")
        ->check(CLI::Range(16, 8192));
    b->add_option("--jump", build.max_jump_px,
                  "with --budget: largest jump (pixels at the stone's rim) when the shown view "
                  "changes; sets the spacing")
        ->check(CLI::Range(0.1, 1000.0))
        ->capture_default_str();
    b->add_flag("--choose-only", build.choose_only,
                "with --budget: print the chosen parameters and build nothing")
        ->needs(budget);
    for (const char* chosen : {"--levels", "--spacing", "--depth", "--threshold"})
        budget->excludes(b->get_option(chosen));
    budget->excludes(dispersion);
    b->add_option("--jobs", build.jobs, "tracing threads (default: every core)")
        ->check(CLI::Range(1, 1024));
    b->add_flag("--idle", build.idle,
                "run at idle CPU priority (SCHED_IDLE, nice 19): for a build beside a display");
    b->add_option("--memory-mb", build.memory_mb,
                  "fail with one message rather than use more address space than this")
        ->check(CLI::Range(16, 1 << 20));

    std::string info_db;
    CLI::App* i = app.add_subcommand("info", "header, stone, parameters and sizes of a database");
    i->add_option("database", info_db, "database (.gemdb)")->required();

    std::string piece_in, piece_out;
    bool piece_check = false;
    CLI::App* p = app.add_subcommand(
        "piece",
        "a piece (.toml, .glb, .gltf) written as glTF 2.0 (.glb) for a web catalogue, "
        "or checked (--check)");
    p->add_option("piece", piece_in, "piece description (.toml) or glTF file")->required();
    CLI::Option* piece_out_option = p->add_option("-o,--out", piece_out, "the .glb to write");
    p->add_flag("--check", piece_check,
                "read the piece and report, without rendering: the stones found and the "
                "evidence for each, the repairs made, the metal, the load time")
        ->excludes(piece_out_option);

    CatalogueOptions catalogue;
    CLI::App* c = app.add_subcommand(
        "catalogue", "a folder of designs into a kiosk catalogue (tables only where they pay)");
    c->add_option("designs", catalogue.designs_dir,
                  "folder of stone descriptions (.toml) and models (.asc, .obj, .stl)")
        ->required();
    c->add_option("-o,--out", catalogue.out, "catalogue folder to write")->required();
    c->add_option("--name", catalogue.name, "the catalogue's name")->capture_default_str();
    c->add_option("--material", catalogue.material, "material of the model files")
        ->capture_default_str();
    c->add_option("--levels", catalogue.build.levels, "tables: image sides per view, ascending")
        ->delimiter(',')
        ->capture_default_str();
    c->add_option("--spacing", catalogue.build.spacing_deg, "tables: angle between stored views")
        ->check(CLI::Range(0.05, 90.0))
        ->capture_default_str();
    c->add_option("--min-elevation", catalogue.build.min_elevation_deg,
                  "tables: lowest view elevation stored (degrees)")
        ->check(CLI::Range(-90.0, 89.0))
        ->capture_default_str();
    c->add_option("--jobs", catalogue.build.jobs, "tracing threads (default: every core)")
        ->check(CLI::Range(1, 1024));
    c->add_option("--sign", catalogue.secret_key,
                  "sign the manifest with this minisign secret key (as gemtables seal --sign)");
    c->add_option("--deb", catalogue.deb.version,
                  "also make a Debian package of this version (as gemtables package)");

    SealOptions seal;
    CLI::App* s = app.add_subcommand(
        "seal",
        "name every file of a catalogue with its BLAKE2b digest in the manifest, and sign it");
    s->add_option("catalogue", seal.catalogue_dir, "catalogue folder")->required();
    s->add_option("--sign", seal.secret_key, "minisign secret key file to sign the manifest with");

    PackageOptions package;
    CLI::App* k = app.add_subcommand(
        "package", "a sealed catalogue as a Debian package for a chain's apt repository");
    k->add_option("catalogue", package.catalogue_dir, "catalogue folder")->required();
    k->add_option("--version", package.version, "the package's version, e.g. 2027.1")->required();
    k->add_option("--package", package.package,
                  "package name (default: gemkiosk-catalogue-<catalogue name>)");
    k->add_option("-o,--out-dir", package.out_dir, "folder for the .deb (default: beside it)");
    k->add_option("--maintainer", package.maintainer, "the package's Maintainer field")
        ->capture_default_str();

    VerifyOptions verify;
    CLI::App* v = app.add_subcommand(
        "verify", "check every checksum and re-trace a sample of pixels with the exact tracer");
    v->add_option("database", verify.database, "database (.gemdb)")->required();
    v->add_option("--samples", verify.samples, "pixels to re-trace")->capture_default_str();
    v->add_option("--seed", verify.seed, "random seed of the sample")->capture_default_str();

    InspectOptions inspect;
    std::vector<double> direction;
    CLI::App* n = app.add_subcommand("inspect", "one view as PNGs: shaded, and ray-list length");
    n->add_option("database", inspect.database, "database (.gemdb)")->required();
    n->add_option("--view-direction", direction, "AZ,EL in degrees (90 elevation = face-up)")
        ->delimiter(',')
        ->expected(2)
        ->required();
    n->add_option("--level", inspect.level, "level index (default: the finest)")
        ->check(CLI::NonNegativeNumber);
    n->add_option("-o,--out", inspect.prefix, "prefix of the PNG files")->required();

    CLI11_PARSE(app, argc, argv);

    if (b->parsed()) {
        if (const std::string bad = check_levels(build.levels); !bad.empty()) {
            return fail("--levels: " + bad);
        }
        // A thread that cannot start (its stack refused under --memory-mb) throws here.
        try {
            return run_build(build);
        } catch (const std::exception& e) {
            return fail(std::string("build stopped: ") + e.what() +
                        (build.memory_mb > 0
                             ? " (under --memory-mb " + std::to_string(build.memory_mb) + ")"
                             : std::string()));
        }
    }
    if (c->parsed()) {
        if (const std::string bad = check_levels(catalogue.build.levels); !bad.empty()) {
            return fail("--levels: " + bad);
        }
        return run_catalogue(catalogue);
    }
    if (s->parsed()) return run_seal(seal);
    if (k->parsed()) return run_package(package);
    if (i->parsed()) return run_info(info_db);
    if (p->parsed()) {
        if (piece_check) return run_piece_check(piece_in);
        if (piece_out.empty()) return fail("piece: give --out FILE.glb to write, or --check");
        return run_piece(piece_in, piece_out);
    }
    if (v->parsed()) return run_verify(verify);
    inspect.azimuth_deg = direction[0];
    inspect.elevation_deg = direction[1];
    if (inspect.elevation_deg < -90.0 || inspect.elevation_deg > 90.0) {
        return fail("--view-direction: the elevation must lie in -90 .. 90 degrees");
    }
    return run_inspect(inspect);
}
