#pragma once
// Who made a catalogue, and that it is whole. Where the kiosk's config lists trusted keys, a
// catalogue's manifest must carry a minisign signature by one of them beside it
// (catalogue.toml.minisig), and the manifest's [blake2b] table must name every other file of
// the directory with its digest. Both are checked before any other file is parsed
// (validate.hpp), so a stranger's file never reaches the kiosk's readers. Digests a manifest
// gives are checked even without keys: they also find a file damaged or half written.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "catalogue/minisign.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

struct CatalogueTrust {
    // Whether catalogues must be signed: the config lists keys. A key file that cannot be read
    // is left out of `keys`, never the requirement, so a typo refuses deliveries instead of
    // opening the kiosk to everyone's.
    bool required = false;
    std::vector<MinisignKey> keys;
};

// A trusted key as the config names it, with its file's bytes: read at start, or kept with the
// last good config (kiosk/settings/last_good_config.hpp), so this library opens no key file.
struct TrustedKeyText {
    std::string source;  // the file's path, for messages
    std::string text;
};

// The trust of config [catalogue] trusted_keys: `required` when the config asks for signatures
// (it lists keys, or its list was unreadable). A key that does not parse is left out and adds a
// message naming it to `problems`.
CatalogueTrust parse_trust(bool required, const std::vector<TrustedKeyText>& keys,
                           std::vector<std::string>& problems);

// `manifest` (dir/catalogue.toml's bytes) against dir/catalogue.toml.minisig: the id of the key
// that signed it, or why it is refused ("not signed: no catalogue.toml.minisig", ...).
Result<std::string> check_manifest_signature(const std::filesystem::path& dir,
                                             std::string_view manifest,
                                             const CatalogueTrust& trust);

}  // namespace gem::kiosk
