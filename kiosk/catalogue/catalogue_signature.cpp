#include "catalogue/catalogue_signature.hpp"

#include <fstream>
#include <system_error>

#include "delivery/catalogue_files.hpp"

namespace gem::kiosk {

namespace fs = std::filesystem;

CatalogueTrust parse_trust(bool required, const std::vector<TrustedKeyText>& keys,
                           std::vector<std::string>& problems) {
    CatalogueTrust trust;
    trust.required = required || !keys.empty();
    for (const TrustedKeyText& text : keys) {
        Result<MinisignKey> key = parse_public_key(text.text, text.source);
        if (key) {
            trust.keys.push_back(std::move(key).value());
        } else {
            problems.push_back(key.error());
        }
    }
    return trust;
}

Result<std::string> check_manifest_signature(const fs::path& dir, std::string_view manifest,
                                             const CatalogueTrust& trust) {
    const fs::path path = dir / tables::kSignatureName;
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(path, ec))) {
        return Error{std::string("not signed (no ") + tables::kSignatureName + ")"};
    }
    if (!fs::is_regular_file(fs::symlink_status(path, ec))) {
        return Error{std::string(tables::kSignatureName) + ": not a regular file"};
    }
    std::ifstream in(path, std::ios::binary);
    // A signature is four short lines; reading a little past that is enough to refuse more.
    std::string text(64 * 1024 + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad() || !in.is_open())
        return Error{std::string(tables::kSignatureName) + ": cannot read"};
    text.resize(static_cast<std::size_t>(in.gcount()));
    Result<MinisignSignature> signature = parse_signature(text);
    if (!signature) return Error{std::string(tables::kSignatureName) + ": " + signature.error()};
    if (trust.keys.empty()) {
        return Error{std::string(tables::kSignatureName) + ": signed by key " +
                     key_id_text(signature.value().key_id) +
                     ", but none of the trusted key files could be read (see the start-up log)"};
    }
    Result<const MinisignKey*> key = verify_signature(manifest, signature.value(), trust.keys);
    if (!key) return Error{std::string(tables::kSignatureName) + ": " + key.error()};
    return key_id_text(key.value()->id);
}

}  // namespace gem::kiosk
