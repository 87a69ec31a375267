#pragma once
// The last config that parsed and validated, kept in the kiosk's state folder with the bytes
// of every key file it trusted, so that a config that later does not parse falls back to what
// the shop last set (its display, touch calibration, looks) and to the keys it last trusted,
// not to the built-in defaults, which trust no key.
//
// One file, state/last-good-config.toml, written whole or not at all (util/atomic_file.hpp):
//   source = "/etc/gemkiosk/gemkiosk.toml"     where it was read (its relative paths start there)
//   config = """..."""                          the file's text
//   [[key]]  file = "chain.pub"  text = """untrusted comment: ...\nRWQ...\n"""
// It lives in the state folder the kiosk is started with (--state-dir, else the one systemd's
// StateDirectory= makes and names in $STATE_DIRECTORY), never one the config names: a config
// that cannot be read cannot say where its copy is. A kiosk started with neither (by hand, in
// tests) keeps no copy.

#include <filesystem>
#include <string>
#include <vector>

#include "util/result.hpp"

namespace gem::kiosk {

inline constexpr const char* kLastGoodConfigName = "last-good-config.toml";

struct KeptKey {
    std::filesystem::path file;  // as the config resolved it
    std::string text;            // the key file's bytes
    bool operator==(const KeptKey&) const = default;
};

struct KeptConfig {
    std::filesystem::path source;  // the config file it was read from
    std::string text;
    std::vector<KeptKey> keys;  // [catalogue] trusted_keys, in the config's order
    bool operator==(const KeptConfig&) const = default;
};

// Writes state_dir/last-good-config.toml unless it already holds exactly `kept` (a kiosk's
// flash is not rewritten at every start). True when it wrote.
Result<bool> keep_last_good_config(const std::filesystem::path& state_dir, const KeptConfig& kept);

// The copy kept in state_dir; an error when there is none or it is damaged.
Result<KeptConfig> read_last_good_config(const std::filesystem::path& state_dir);

}  // namespace gem::kiosk
