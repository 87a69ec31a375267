// libFuzzer target: any bytes handed to the readers a delivered catalogue meets first, before
// its signature is known to be good: minisign's public key and signature readers (and the
// check of a signature read, against a fixed key), and the catalogue manifest's reader. Each
// must answer with a result or an Error, never a crash, a sanitizer report or an assertion.
// Seeds: tests/fixtures/signature (a key, a signed manifest and both forms of its signature).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "catalogue/manifest.hpp"
#include "catalogue/minisign.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    static const gem::kiosk::MinisignKey key = [] {
        gem::kiosk::MinisignKey k;
        k.public_key.fill(7);
        return k;
    }();
    (void)gem::kiosk::parse_public_key(text, "fuzz.pub");
    auto signature = gem::kiosk::parse_signature(text);
    if (signature) {
        gem::kiosk::MinisignSignature s = signature.value();
        s.key_id = key.id;  // so that the Ed25519 checks run on what was read
        (void)gem::kiosk::verify_signature(text, s, {key});
    }
    (void)gem::kiosk::parse_manifest(text, "/catalogue");
    return 0;
}
