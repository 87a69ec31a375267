#include "catalogue/minisign.hpp"

#include <sodium.h>

#include <cstdio>

namespace gem::kiosk {

namespace {

constexpr std::string_view kUntrusted = "untrusted comment: ";
constexpr std::string_view kTrusted = "trusted comment: ";
// A key or signature file is a few hundred bytes; anything much larger is not one.
constexpr std::size_t kLargestFile = 64 * 1024;

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return lines;
}

// Exactly `size` bytes from one line of base64 (RFC 4648, with padding), or nothing.
template <std::size_t N>
bool decode_exact(std::string_view line, std::array<std::uint8_t, N>& out) {
    std::size_t length = 0;
    const char* end = nullptr;
    if (sodium_base642bin(out.data(), out.size(), line.data(), line.size(), nullptr, &length, &end,
                          sodium_base64_VARIANT_ORIGINAL) != 0) {
        return false;
    }
    return length == N && end == line.data() + line.size();
}

bool starts_with(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

}  // namespace

std::string key_id_text(const std::array<std::uint8_t, 8>& id) {
    std::string out;
    for (std::size_t i = id.size(); i-- > 0;) {
        char hex[3];
        std::snprintf(hex, sizeof hex, "%02X", id[i]);
        out += hex;
    }
    // minisign prints the id with "%" PRIX64, so without leading zeros; staff compare the two.
    const std::size_t first = out.find_first_not_of('0');
    return first == std::string::npos ? "0" : out.substr(first);
}

Result<MinisignKey> parse_public_key(std::string_view text, const std::string& source) {
    std::string_view encoded;
    for (const std::string_view line : split_lines(text)) {
        if (line.empty() || starts_with(line, kUntrusted)) continue;
        if (!encoded.empty()) return Error{source + ": more than one key line"};
        encoded = line;
    }
    if (encoded.empty()) return Error{source + ": no key (a minisign public key file has one)"};
    std::array<std::uint8_t, 42> raw{};
    if (!decode_exact(encoded, raw)) {
        return Error{source +
                     ": not a minisign public key (its key line must be 56 base64 "
                     "characters)"};
    }
    if (raw[0] != 'E' || raw[1] != 'd') {
        return Error{source + ": not an Ed25519 minisign key"};
    }
    MinisignKey key;
    std::copy(raw.begin() + 2, raw.begin() + 10, key.id.begin());
    std::copy(raw.begin() + 10, raw.end(), key.public_key.begin());
    key.source = source;
    return key;
}

Result<MinisignSignature> parse_signature(std::string_view text) {
    if (text.size() > kLargestFile) return Error{"too large for a minisign signature"};
    std::vector<std::string_view> lines = split_lines(text);
    while (!lines.empty() && lines.back().empty()) lines.pop_back();
    if (lines.size() != 4) {
        return Error{"not a minisign signature (it has " + std::to_string(lines.size()) +
                     " lines, a signature 4: it may be cut short)"};
    }
    if (!starts_with(lines[0], kUntrusted)) {
        return Error{"not a minisign signature (line 1 is not an untrusted comment)"};
    }
    std::array<std::uint8_t, 74> raw{};
    if (!decode_exact(lines[1], raw)) {
        return Error{"damaged minisign signature (line 2 is not 74 bytes of base64)"};
    }
    MinisignSignature sig;
    if (raw[0] == 'E' && raw[1] == 'D') {
        sig.prehashed = true;
    } else if (raw[0] == 'E' && raw[1] == 'd') {
        sig.prehashed = false;
    } else {
        return Error{"unknown minisign signature algorithm"};
    }
    std::copy(raw.begin() + 2, raw.begin() + 10, sig.key_id.begin());
    std::copy(raw.begin() + 10, raw.end(), sig.signature.begin());
    if (!starts_with(lines[2], kTrusted)) {
        return Error{"damaged minisign signature (line 3 is not a trusted comment)"};
    }
    sig.trusted_comment = std::string(lines[2].substr(kTrusted.size()));
    if (!decode_exact(lines[3], sig.global_signature)) {
        return Error{"damaged minisign signature (line 4 is not 64 bytes of base64)"};
    }
    return sig;
}

Result<const MinisignKey*> verify_signature(std::string_view message,
                                            const MinisignSignature& signature,
                                            const std::vector<MinisignKey>& keys) {
    if (sodium_init() < 0) return Error{"libsodium cannot start"};
    const MinisignKey* key = nullptr;
    for (const MinisignKey& k : keys) {
        if (k.id == signature.key_id) key = &k;
    }
    if (key == nullptr) {
        std::string trusted;
        for (const MinisignKey& k : keys) {
            trusted += (trusted.empty() ? "" : ", ") + key_id_text(k.id);
        }
        return Error{"signed by key " + key_id_text(signature.key_id) +
                     ", which is not trusted (trusted: " + trusted + ")"};
    }
    const auto* bytes = reinterpret_cast<const unsigned char*>(message.data());
    int verified = -1;
    if (signature.prehashed) {
        std::array<unsigned char, crypto_generichash_BYTES_MAX> digest{};  // BLAKE2b-512
        crypto_generichash(digest.data(), digest.size(), bytes, message.size(), nullptr, 0);
        verified = crypto_sign_verify_detached(signature.signature.data(), digest.data(),
                                               digest.size(), key->public_key.data());
    } else {
        verified = crypto_sign_verify_detached(signature.signature.data(), bytes, message.size(),
                                               key->public_key.data());
    }
    if (verified != 0) {
        return Error{"the signature by key " + key_id_text(key->id) +
                     " does not match (the file was changed after signing, or the signature is "
                     "another file's)"};
    }
    std::string global(signature.signature.begin(), signature.signature.end());
    global += signature.trusted_comment;
    if (crypto_sign_verify_detached(signature.global_signature.data(),
                                    reinterpret_cast<const unsigned char*>(global.data()),
                                    global.size(), key->public_key.data()) != 0) {
        return Error{"the signature's trusted comment was changed after signing"};
    }
    return key;
}

}  // namespace gem::kiosk
