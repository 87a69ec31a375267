#pragma once
// Which config the kiosk runs on, and what it trusts, when the file is not as it should be.
// Security fails closed and the shop's settings stand:
//   - the file reads and parses: it is used, each bad line keeping its key's default; if it is
//     also free of errors and every trusted key file reads, it is the one to keep as the last
//     good config (last_good_config.hpp);
//   - it cannot be read or does not parse: the last good config stands instead (its display,
//     touch calibration, looks and the keys it trusted, as kept), or the built-in defaults when
//     none was ever kept; either way no new catalogue is accepted until the file is fixed;
//   - it parses with errors and lists no trusted key where the last good config did (a table
//     misspelt, `[catalouge]`): the kept keys are still required, so a typo never turns
//     signature checks off.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "settings/kiosk_config.hpp"
#include "settings/last_good_config.hpp"

namespace gem::kiosk {

struct ResolvedConfig {
    KioskConfig config;
    // Each an error line for the journal, in the file's order; a line that sets the file aside
    // says what stands instead.
    std::vector<std::string> errors;
    // The keys catalogues must be signed with, as read now or as kept with the last good
    // config. `config.catalogue.trusted_keys_unreadable` or any key here makes signatures
    // required.
    std::vector<KeptKey> trusted_keys;
    bool signatures_required = false;
    // Why no delivered catalogue may be installed (empty: they may be): the file could not be
    // read or parsed. Said at every delivery.
    std::string deliveries_refused_because;
    // The file as it is, to keep as the last good config: it parsed without one error and every
    // key file it names was read. The caller keeps it once the keys also parse.
    std::optional<KeptConfig> good;
};

// Reads the trusted key files a config names; each that cannot be read (or is too large to be
// a key) adds an error line naming it and is left out.
std::vector<KeptKey> read_trusted_key_files(const std::vector<std::filesystem::path>& files,
                                            std::vector<std::string>& errors);

// Reads `file`; `state_dir` is where the last good config is kept (last_good_config.hpp), empty
// when the kiosk has no state folder of its own to keep one in.
ResolvedConfig resolve_config(const std::filesystem::path& file,
                              const std::filesystem::path& state_dir);

}  // namespace gem::kiosk
