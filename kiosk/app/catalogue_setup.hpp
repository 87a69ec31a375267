#pragma once
// What the kiosk's catalogues are found, trusted and installed with, from the config it runs on
// (settings/config_fallback.hpp): the folders, the keys (read now, or kept with the last good
// config), and whether deliveries are refused while the config is set aside. Also where the
// last good config is kept.

#include <filesystem>
#include <string>
#include <vector>

#include "app/kiosk_run.hpp"
#include "catalogue/catalogue.hpp"
#include "settings/config_fallback.hpp"

namespace gem::kiosk {

// The trust of kept or freshly read key texts (settings/last_good_config.hpp): each that does
// not parse as a minisign key adds "trusted key left out: FILE: why" to `problems`.
CatalogueTrust trust_of_keys(bool required, const std::vector<KeptKey>& keys,
                             std::vector<std::string>& problems);

// --state-dir, else systemd's StateDirectory= ($STATE_DIRECTORY), else none (empty).
std::filesystem::path started_state_dir(const KioskRun& run);

// The catalogue options for `config` (the resolved one, with the command line's overrides).
// Logs the trust once (its keys, or that there are none); keeps the config as the last good one
// in `kept_in` where it and every key are good.
CatalogueOptions catalogue_setup(const KioskConfig& config, const ResolvedConfig& resolved,
                                 const std::filesystem::path& kept_in);

}  // namespace gem::kiosk
