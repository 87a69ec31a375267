#include "settings/config_fallback.hpp"

#include <cstdint>

#include "import/import_text.hpp"

namespace gem::kiosk {

namespace fs = std::filesystem;

namespace {

Result<KeptConfig> kept_config(const fs::path& state_dir) {
    if (state_dir.empty()) {
        return Error{
            "the kiosk was started without a state folder to keep one in: --state-dir, "
            "or systemd's StateDirectory="};
    }
    return read_last_good_config(state_dir);
}

// The file could not be read or parsed (`why`, its one error line): the last good config
// stands, or the defaults; no delivery is accepted.
ResolvedConfig set_aside(const std::string& why, const fs::path& state_dir) {
    ResolvedConfig out;
    out.deliveries_refused_because =
        "the config is set aside (" + why + "), so no new catalogue is accepted until it is fixed";
    auto kept = kept_config(state_dir);
    if (!kept) {
        out.errors.push_back(why +
                             "; the whole file is set aside and the built-in defaults are "
                             "used, as no good config was kept (" +
                             kept.error() + "); no new catalogue is accepted until it is fixed");
        return out;
    }
    const KeptConfig& good = kept.value();
    const ConfigLoad load =
        parse_config(good.text, (state_dir / kLastGoodConfigName).string() + " (config)",
                     good.source.parent_path());
    out.config = load.config;
    out.trusted_keys = good.keys;
    out.signatures_required = !good.keys.empty();
    out.errors.push_back(why + "; the whole file is set aside and the last good config (" +
                         good.source.string() + " as kept in " +
                         (state_dir / kLastGoodConfigName).string() +
                         ") is used; no new catalogue is accepted until it is fixed");
    // A kept config was free of errors when kept; one that is not now (a newer kiosk dropped a
    // key) still says so.
    out.errors.insert(out.errors.end(), load.errors.begin(), load.errors.end());
    return out;
}

}  // namespace

std::vector<KeptKey> read_trusted_key_files(const std::vector<fs::path>& files,
                                            std::vector<std::string>& errors) {
    // A minisign public key is two short lines; a larger file is not one (nor read whole).
    constexpr std::uintmax_t kLargestKeyFile = 4096;
    std::vector<KeptKey> keys;
    for (const fs::path& file : files) {
        // Never opened unless a regular file: a FIFO or /dev/zero named by mistake would stall
        // the start.
        std::error_code ec;
        const fs::file_status status = fs::status(file, ec);
        const bool regular = !ec && fs::is_regular_file(status);
        const std::uintmax_t size = regular ? fs::file_size(file, ec) : 0;
        Result<std::string> text = Error{""};
        if (ec) {
            text = Error{file.string() + ": cannot open (" + ec.message() + ")"};
        } else if (!regular) {
            text = Error{file.string() + ": not a regular file"};
        } else if (size > kLargestKeyFile) {
            text = Error{file.string() + ": not a key file (too large)"};
        } else {
            text = import::read_whole_file(file);
        }
        if (text) {
            keys.push_back(KeptKey{file, std::move(text).value()});
        } else {
            errors.push_back("trusted key left out: " + text.error() +
                             "; catalogues signed with it will be refused");
        }
    }
    return keys;
}

ResolvedConfig resolve_config(const fs::path& file, const fs::path& state_dir) {
    auto text = import::read_whole_file(file);
    if (!text) return set_aside(text.error(), state_dir);
    ConfigLoad load = parse_config(text.value(), file.string(), file.parent_path());
    if (!load.parsed) return set_aside(load.errors.front(), state_dir);

    ResolvedConfig out;
    out.config = std::move(load.config);
    out.errors = std::move(load.errors);
    const bool config_clean = out.errors.empty();
    const CatalogueConfig& catalogue = out.config.catalogue;
    out.trusted_keys = read_trusted_key_files(catalogue.trusted_keys, out.errors);
    out.signatures_required = !catalogue.trusted_keys.empty() || catalogue.trusted_keys_unreadable;
    if (config_clean && out.errors.empty()) {
        out.good = KeptConfig{file, std::move(text).value(), out.trusted_keys};
    }
    if (!config_clean && !out.signatures_required) {
        if (auto kept = kept_config(state_dir); kept && !kept.value().keys.empty()) {
            out.trusted_keys = kept.value().keys;
            out.signatures_required = true;
            out.errors.push_back(
                file.string() +
                ": lists no trusted key but has errors, while the last good config "
                "(kept in " +
                (state_dir / kLastGoodConfigName).string() + ") trusted " +
                std::to_string(kept.value().keys.size()) +
                (kept.value().keys.size() == 1 ? " key" : " keys") +
                ": catalogues must still be signed by them");
        }
    }
    return out;
}

}  // namespace gem::kiosk
