// gemtables catalogue: a folder of designs into a kiosk catalogue. Each design is a stone
// description (.toml, config/stones/README.md) or a model file (GemCad .asc, OBJ, STL) given
// the --material; every one is checked by building its stone. Tables are built only where they
// pay: a convex stone is drawn exactly by the kiosk's trace, which needs none (README, "Cost
// follows the stone"); a stone that is not convex would make the trace test every triangle,
// hundreds of times slower (the heart: 4.3 s a frame), so it gets a database built with the
// build options. One progress line per stone; a design that cannot be read is left out with
// its message, and the rest still make the catalogue.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "commands.hpp"
#include "delivery/catalogue_files.hpp"
#include "scene/stone_file.hpp"
#include "util/atomic_file.hpp"

namespace gem::tables {

namespace {

namespace fs = std::filesystem;

bool is_model(const fs::path& file) {
    std::string e = file.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e == ".asc" || e == ".obj" || e == ".stl";
}

}  // namespace

int run_catalogue(const CatalogueOptions& o) {
    std::error_code ec;
    std::vector<fs::path> designs;
    for (const auto& entry : fs::directory_iterator(o.designs_dir, ec)) {
        const fs::path& p = entry.path();
        if (entry.is_regular_file() && (p.extension() == ".toml" || is_model(p))) {
            designs.push_back(p);
        }
    }
    if (ec) return fail(o.designs_dir + ": " + ec.message());
    std::sort(designs.begin(), designs.end());
    if (designs.empty()) return fail(o.designs_dir + ": no designs (.toml, .asc, .obj, .stl)");
    const fs::path out(o.out);
    fs::create_directories(out, ec);
    if (ec) return fail(o.out + ": " + ec.message());

    std::string manifest = "[catalogue]\nname = " + toml_string(o.name) + "\n";
    int written = 0;
    std::vector<std::string> stems, names;
    for (std::size_t i = 0; i < designs.size(); ++i) {
        const fs::path& source = designs[i];
        const std::string stem = source.stem().string();
        char head[64];
        std::snprintf(head, sizeof head, "gemtables: %zu/%zu ", i + 1, designs.size());
        if (std::find(stems.begin(), stems.end(), stem) != stems.end()) {
            std::printf("%s%s: left out: another design is also called '%s'\n", head,
                        source.filename().c_str(), stem.c_str());
            continue;
        }
        stems.push_back(stem);
        // Every stone gets a description in the catalogue: a model is named by one that adds
        // the material.
        fs::path description = out / (stem + ".toml");
        if (is_model(source)) {
            fs::copy_file(source, out / source.filename(), fs::copy_options::overwrite_existing,
                          ec);
            const std::string text = "[stone]\nmodel = " + toml_string(source.filename().string()) +
                                     "\n\n[material]\nname = " + toml_string(o.material) + "\n";
            if (!ec) {
                auto made = write_file_atomic(description, text.data(), text.size());
                if (!made) ec = std::make_error_code(std::errc::io_error);
            }
        } else {
            fs::copy_file(source, description, fs::copy_options::overwrite_existing, ec);
        }
        if (ec) return fail(description.string() + ": " + ec.message());
        const auto start = std::chrono::steady_clock::now();
        Result<Stone> stone = load_stone_file(description);
        if (!stone) {
            // The message names the copy; staff know their own file.
            std::string why = stone.error();
            if (why.rfind(description.string(), 0) == 0 && !is_model(source)) {
                why = source.string() + why.substr(description.string().size());
            }
            std::printf("%s%s: left out: %s\n", head, source.filename().c_str(), why.c_str());
            fs::remove(description, ec);
            continue;
        }
        // Names are unique in a catalogue: a second stone of the same name takes its file's.
        std::string name = stone.value().name.empty() ? stem : stone.value().name;
        if (std::find(names.begin(), names.end(), name) != names.end()) name += " (" + stem + ")";
        names.push_back(name);
        manifest += "\n[[stone]]\nname = " + toml_string(name);
        if (stone.value().convex) {
            manifest += "\ndesign = " + toml_string(description.filename().string()) + "\n";
            std::printf("%s%s: convex, %zu facets: shown by the exact trace, no tables\n", head,
                        source.filename().c_str(), stone.value().facets.size());
        } else {
            std::printf("%s%s: not convex, %zu facets: building tables\n", head,
                        source.filename().c_str(), stone.value().facets.size());
            std::fflush(stdout);
            BuildOptions build = o.build;
            build.stone_file = description.string();
            build.out = (out / (stem + ".gemdb")).string();
            if (run_build(build) != 0) {
                std::printf("%s%s: left out: its tables could not be built\n", head,
                            source.filename().c_str());
                continue;
            }
            manifest += "\ndatabase = " + toml_string(stem + ".gemdb") + "\n";
            std::printf(
                "%s%s: tables in %.1f s\n", head, source.filename().c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        std::fflush(stdout);
        ++written;
    }
    if (written == 0) return fail("no design could be read: nothing to put in a catalogue");
    auto made = write_file_atomic(out / "catalogue.toml", manifest.data(), manifest.size());
    if (!made) return fail(made.error());
    std::printf("gemtables: wrote %s: %d of %zu designs\n", (out / "catalogue.toml").c_str(),
                written, designs.size());
    // Every file named with its digest (signed where a key is given), then packaged.
    if (const int sealed = run_seal({o.out, o.secret_key}); sealed != 0) return sealed;
    if (o.deb.version.empty()) return 0;
    PackageOptions deb = o.deb;
    deb.catalogue_dir = o.out;
    return run_package(deb);
}

}  // namespace gem::tables
