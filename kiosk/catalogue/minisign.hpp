#pragma once
// minisign's public keys and signatures (https://jedisct1.github.io/minisign/), checked with
// libsodium's Ed25519. A chain signs a catalogue's manifest with the minisign tool; the kiosk
// only verifies, so it holds no secret and needs no minisign installed.
//
// Public key file (minisign -G):       Signature file (minisign -S, <file>.minisig):
//   untrusted comment: <text>            untrusted comment: <text>
//   base64("Ed" | key id[8] | pk[32])    base64(alg[2] | key id[8] | signature[64])
//                                        trusted comment: <text>
//                                        base64(global signature[64])
// alg "Ed" signs the file itself, "ED" (minisign's default since 0.10) its BLAKE2b-512
// digest. The global signature signs signature[64] followed by the trusted comment's text, so
// the trusted comment (a timestamp and the file's name) cannot be changed either.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.hpp"

namespace gem::kiosk {

struct MinisignKey {
    std::array<std::uint8_t, 8> id{};
    std::array<std::uint8_t, 32> public_key{};
    std::string source;  // where it came from (a file name), for messages
};

struct MinisignSignature {
    bool prehashed = true;  // "ED": signs BLAKE2b-512(message)
    std::array<std::uint8_t, 8> key_id{};
    std::array<std::uint8_t, 64> signature{};
    std::string trusted_comment;
    std::array<std::uint8_t, 64> global_signature{};
};

// The key id as minisign prints it: the 8 bytes as a little-endian number in upper-case hex,
// without leading zeros ("A907ACA8EAC94A85", "60DB93A0BCE91DC").
std::string key_id_text(const std::array<std::uint8_t, 8>& id);

// A public key file's text (its comment line is optional, so minisign's -P string also works).
Result<MinisignKey> parse_public_key(std::string_view text, const std::string& source);

Result<MinisignSignature> parse_signature(std::string_view text);

// Whether `signature` signs `message` with one of `keys`: the key that signed it, or why not
// ("signed by key X, which is not trusted", "does not match", ...).
Result<const MinisignKey*> verify_signature(std::string_view message,
                                            const MinisignSignature& signature,
                                            const std::vector<MinisignKey>& keys);

}  // namespace gem::kiosk
