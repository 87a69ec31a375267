#include "app/catalogue_setup.hpp"

#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "service/log.hpp"

namespace gem::kiosk {

namespace {

// The trust catalogues are checked with: the keys the config trusts now, or those kept with the
// last good config when it is set aside (settings/config_fallback.hpp).
CatalogueTrust trust_of(const ResolvedConfig& resolved, std::vector<std::string>& problems) {
    CatalogueTrust trust =
        trust_of_keys(resolved.signatures_required, resolved.trusted_keys, problems);
    for (const std::string& problem : problems) {
        log_error(problem + "; catalogues signed with it will be refused");
    }
    if (!trust.required) {
        log_warning(
            "catalogues are not authenticated: [catalogue] trusted_keys lists no key, so "
            "any well-formed catalogue in the inbox or a watched folder is shown");
    } else if (trust.keys.empty()) {
        log_error("no trusted key could be read: every delivered catalogue will be refused");
    } else {
        std::string keys;
        for (const MinisignKey& key : trust.keys) {
            keys += (keys.empty() ? "" : ", ") + key_id_text(key.id) + " (" + key.source + ")";
        }
        log_info("catalogues must be signed by a trusted key: " + keys);
    }
    return trust;
}

CatalogueOptions options_of(const KioskConfig& config, const ResolvedConfig& resolved) {
    CatalogueOptions options;
    options.inbox_dir = config.catalogue.inbox_dir;
    options.extra_dirs = config.catalogue.watch_dirs;
    options.state_dir = config.catalogue.state_dir;
    options.default_catalogue = config.catalogue.default_dir;
    options.settle_time =
        std::chrono::milliseconds(static_cast<long>(config.catalogue.settle_s * 1000.0));
    options.deliveries_refused_because = resolved.deliveries_refused_because;
    return options;
}

// Keeps a config that parsed, validated and whose keys all parse as the last good one.
void keep_if_good(const ResolvedConfig& resolved, bool keys_parsed,
                  const std::filesystem::path& state_dir) {
    if (!resolved.good || !keys_parsed || state_dir.empty()) return;
    auto kept = keep_last_good_config(state_dir, *resolved.good);
    if (!kept) {
        log_warning("the config could not be kept as the last good one: " + kept.error());
    } else if (kept.value()) {
        log_info("config " + resolved.good->source.string() + " kept as the last good one in " +
                 (state_dir / kLastGoodConfigName).string());
    }
}

}  // namespace

CatalogueTrust trust_of_keys(bool required, const std::vector<KeptKey>& keys,
                             std::vector<std::string>& problems) {
    std::vector<TrustedKeyText> texts;
    for (const KeptKey& key : keys) texts.push_back(TrustedKeyText{key.file.string(), key.text});
    std::vector<std::string> unparsed;
    CatalogueTrust trust = parse_trust(required, texts, unparsed);
    for (const std::string& why : unparsed) problems.push_back("trusted key left out: " + why);
    return trust;
}

// --state-dir, else systemd's StateDirectory= ($STATE_DIRECTORY, systemd.exec(5): "a
// colon-separated list" of the unit's state directories; this unit has one), else none.
std::filesystem::path started_state_dir(const KioskRun& run) {
    if (run.state_dir) return *run.state_dir;
    const char* from_systemd = std::getenv("STATE_DIRECTORY");
    if (from_systemd == nullptr) return {};
    const std::string_view dirs(from_systemd);
    return std::filesystem::path(dirs.substr(0, dirs.find(':')));
}

CatalogueOptions catalogue_setup(const KioskConfig& config, const ResolvedConfig& resolved,
                                 const std::filesystem::path& kept_in) {
    CatalogueOptions options = options_of(config, resolved);
    std::vector<std::string> key_problems;
    options.trust = trust_of(resolved, key_problems);
    keep_if_good(resolved, key_problems.empty(), kept_in);
    return options;
}

}  // namespace gem::kiosk
