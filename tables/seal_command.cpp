// gemtables seal: a catalogue's manifest names every other file with its BLAKE2b digest
// (delivery/catalogue_files.hpp), and is signed with the chain's minisign key, so that a kiosk that
// trusts the key shows exactly these files. Signing runs the minisign tool itself: a chain
// keeps its secret key where minisign keeps it, encrypted with a password that minisign asks
// for on the terminal.
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "commands.hpp"
#include "delivery/catalogue_files.hpp"
#include "run_program.hpp"

namespace gem::tables {

namespace {

namespace fs = std::filesystem;

int sign_manifest(const fs::path& dir, const std::string& secret_key) {
    const std::string manifest = (dir / kManifestName).string();
    // The terminal is the child's too: minisign asks for the key's password there.
    const int signed_ = run_program({"minisign", "-S", "-s", secret_key, "-m", manifest},
                                    "install the minisign package to sign");
    if (signed_ != 0) return fail(manifest + ": minisign did not sign it (its message is above)");
    std::printf("gemtables: signed %s (%s)\n", manifest.c_str(), kSignatureName);
    return 0;
}

}  // namespace

int run_seal(const SealOptions& o) {
    const fs::path dir(o.catalogue_dir);
    Result<std::size_t> named = write_digests(dir);
    if (!named) return fail(named.error());
    std::printf("gemtables: %s names %zu file%s with its BLAKE2b digest\n",
                (dir / kManifestName).c_str(), named.value(), named.value() == 1 ? "" : "s");
    const fs::path signature = dir / kSignatureName;
    std::error_code ec;
    if (o.secret_key.empty()) {
        // The manifest just changed, so an old signature no longer matches it.
        if (fs::remove(signature, ec)) {
            std::printf("gemtables: removed %s, which no longer matched: sign again\n",
                        signature.c_str());
        }
        return 0;
    }
    return sign_manifest(dir, o.secret_key);
}

}  // namespace gem::tables
