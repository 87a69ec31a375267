// Signed catalogues against the minisign tool itself: keys and signatures are made by
// `minisign` (the chain's tool, an implementation independent of the kiosk's check), digests
// are compared with b2sum(1). A good signature (minisign's default prehashed and its
// legacy form) is accepted; a wrong key, a changed, missing or added file, a truncated
// signature, a signature over another manifest and a changed trusted comment are refused,
// each with its own reason, and nothing of a refused catalogue is parsed.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "catalogue/catalogue_signature.hpp"
#include "catalogue/minisign.hpp"
#include "catalogue/validate.hpp"
#include "catalogue_test_support.hpp"
#include "commands.hpp"
#include "delivery/catalogue_files.hpp"

namespace gem::kiosk {
namespace {

namespace fs = std::filesystem;
using namespace catalogue_test;

struct KeyPair {
    fs::path pub, key;
    std::string id;  // as minisign's own comment line gives it
};

KeyPair make_key(const fs::path& dir, const std::string& name) {
    fs::create_directories(dir);
    KeyPair k{dir / (name + ".pub"), dir / (name + ".key"), ""};
    int status = -1;
    const std::string out = run_command(
        "minisign -G -W -p '" + k.pub.string() + "' -s '" + k.key.string() + "'", &status);
    EXPECT_EQ(status, 0) << out;
    const std::string text = read_text(k.pub);
    const std::string marker = "minisign public key ";
    const std::size_t at = text.find(marker);
    EXPECT_NE(at, std::string::npos) << text;
    if (at != std::string::npos) {
        const std::size_t start = at + marker.size();
        k.id = text.substr(start, text.find('\n', start) - start);
    }
    return k;
}

void sign(const fs::path& file, const KeyPair& key, const std::string& extra = "") {
    int status = -1;
    const std::string out = run_command(
        "minisign -S " + extra + " -s '" + key.key.string() + "' -m '" + file.string() + "'",
        &status);
    ASSERT_EQ(status, 0) << out;
}

// A sealed catalogue (gemtables seal) signed with `key`.
fs::path signed_catalogue(const std::string& name, const KeyPair& key,
                          const std::string& extra = "") {
    const fs::path dir = fresh_dir("signed-" + name);
    write_catalogue(dir, name);
    EXPECT_EQ(tables::run_seal({dir.string(), ""}), 0);
    sign(dir / "catalogue.toml", key, extra);
    return dir;
}

CatalogueTrust trusting(const std::vector<KeyPair>& keys) {
    std::vector<TrustedKeyText> texts;
    for (const KeyPair& k : keys) texts.push_back({k.pub.string(), read_text(k.pub)});
    std::vector<std::string> problems;
    CatalogueTrust trust = parse_trust(true, texts, problems);
    EXPECT_TRUE(problems.empty());
    return trust;
}

// The refusal line for `dir`, or "accepted".
std::string verdict(const fs::path& dir, const CatalogueTrust& trust) {
    Result<Catalogue> result = validate_catalogue(dir, trust);
    return result ? std::string("accepted") : result.error();
}

class SignedCatalogue : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        // CTest runs each test as a process of its own, side by side: keys of its own too.
        const fs::path keys = fresh_dir("signature-keys-" + std::to_string(::getpid()));
        chain_ = new KeyPair(make_key(keys, "chain"));
        stranger_ = new KeyPair(make_key(keys, "stranger"));
    }
    static void TearDownTestSuite() {
        delete chain_;
        delete stranger_;
    }
    static KeyPair* chain_;
    static KeyPair* stranger_;
};
KeyPair* SignedCatalogue::chain_ = nullptr;
KeyPair* SignedCatalogue::stranger_ = nullptr;

TEST_F(SignedCatalogue, TheKeyIdIsTheOneMinisignPrints) {
    Result<MinisignKey> key = parse_public_key(read_text(chain_->pub), chain_->pub.string());
    ASSERT_TRUE(key.ok()) << key.error();
    EXPECT_EQ(key_id_text(key.value().id), chain_->id);
}

// Signatures minisign made once and stored: both forms verify against the stored key, and
// fail against the same bytes changed.
TEST(MinisignFixture, StoredSignaturesVerify) {
    const fs::path dir = fs::path(GEM_FIXTURES_DIR) / "signature";
    Result<MinisignKey> key = parse_public_key(read_text(dir / "fixture.pub"), "fixture.pub");
    ASSERT_TRUE(key.ok()) << key.error();
    EXPECT_EQ(key_id_text(key.value().id), "6210369F81C2ADCE");
    std::string manifest = read_text(dir / "manifest.toml");
    for (const char* name : {"manifest.toml.minisig", "manifest.toml.legacy.minisig"}) {
        Result<MinisignSignature> signature = parse_signature(read_text(dir / name));
        ASSERT_TRUE(signature.ok()) << signature.error();
        EXPECT_EQ(signature.value().prehashed,
                  std::string(name).find("legacy") == std::string::npos);
        EXPECT_TRUE(verify_signature(manifest, signature.value(), {key.value()}).ok()) << name;
        std::string changed = manifest;
        changed[changed.size() / 2] ^= 0x20;
        EXPECT_FALSE(verify_signature(changed, signature.value(), {key.value()}).ok()) << name;
    }
}

// minisign prints a key id as a little-endian number, "%" PRIX64: no leading zeros.
TEST(MinisignFixture, AKeyIdIsPrintedAsMinisignPrintsIt) {
    EXPECT_EQ(key_id_text({0xDC, 0x91, 0xCE, 0x0B, 0x3A, 0xB9, 0x0D, 0x06}), "60DB93A0BCE91DC");
    EXPECT_EQ(key_id_text({0x85, 0x4A, 0xC9, 0xEA, 0xA8, 0xAC, 0x07, 0xA9}), "A907ACA8EAC94A85");
    EXPECT_EQ(key_id_text({0, 0, 0, 0, 0, 0, 0, 0}), "0");
}

TEST_F(SignedCatalogue, TheDigestsAreTheFilesBlake2b) {
    const fs::path dir = signed_catalogue("digests", *chain_);
    const std::string expected =
        run_command("cd '" + dir.string() + "' && b2sum stones/round.gemdb").substr(0, 128);
    const std::string manifest = read_text(dir / "catalogue.toml");
    EXPECT_NE(manifest.find("[blake2b]\n\"stones/round.gemdb\" = \"" + expected + "\"\n"),
              std::string::npos)
        << manifest;
    // Sealing again replaces the table rather than adding a second.
    ASSERT_EQ(tables::run_seal({dir.string(), ""}), 0);
    const std::string again = read_text(dir / "catalogue.toml");
    EXPECT_EQ(again, manifest);
    EXPECT_FALSE(fs::exists(dir / "catalogue.toml.minisig"))
        << "a signature the new manifest no longer matches is removed";
}

TEST_F(SignedCatalogue, AGoodSignatureIsAccepted) {
    const fs::path dir = signed_catalogue("good", *chain_);
    Result<Catalogue> result = validate_catalogue(dir, trusting({*stranger_, *chain_}));
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_EQ(result.value().signed_by, chain_->id);
    EXPECT_EQ(result.value().stones.size(), 1u);
}

TEST_F(SignedCatalogue, MinisignsLegacySignatureIsAccepted) {
    const fs::path dir = signed_catalogue("legacy", *chain_, "-l");
    EXPECT_EQ(verdict(dir, trusting({*chain_})), "accepted");
}

TEST_F(SignedCatalogue, AnotherKeysSignatureIsRefused) {
    const fs::path dir = signed_catalogue("stranger", *stranger_);
    EXPECT_EQ(verdict(dir, trusting({*chain_})),
              "catalogue 'signed-stranger' rejected: catalogue.toml.minisig: signed by key " +
                  stranger_->id + ", which is not trusted (trusted: " + chain_->id + ")");
}

TEST_F(SignedCatalogue, AnUnsignedCatalogueIsRefusedUnparsed) {
    const fs::path dir = fresh_dir("signed-none");
    write_catalogue(dir, "none");
    // Not even TOML: the refusal must come before any parsing.
    write_text(dir / "catalogue.toml", "[[[ this is not a manifest");
    EXPECT_EQ(verdict(dir, trusting({*chain_})),
              "catalogue 'signed-none' rejected: not signed (no catalogue.toml.minisig)");
}

TEST_F(SignedCatalogue, AChangedFileIsRefused) {
    const fs::path dir = signed_catalogue("changed", *chain_);
    std::vector<std::uint8_t> bytes = read_bytes(dir / "stones" / "round.gemdb");
    bytes[bytes.size() / 2] ^= 0x10;
    write_bytes(dir / "stones" / "round.gemdb", bytes);
    EXPECT_EQ(verdict(dir, trusting({*chain_})),
              "catalogue 'changed' rejected: stones/round.gemdb: does not match its digest in "
              "the manifest (changed or damaged since the catalogue was made)");
}

TEST_F(SignedCatalogue, AMissingOrAddedFileIsRefused) {
    const fs::path dir = signed_catalogue("missing", *chain_);
    fs::rename(dir / "stones" / "round.gemdb", dir / "round.gemdb");
    EXPECT_EQ(verdict(dir, trusting({*chain_})),
              "catalogue 'missing' rejected: round.gemdb: not named in the manifest's [blake2b] "
              "table (added after signing, or left over from an interrupted installation)");
    fs::remove(dir / "round.gemdb");
    EXPECT_EQ(verdict(dir, trusting({*chain_})),
              "catalogue 'missing' rejected: stones/round.gemdb: missing (the manifest's "
              "[blake2b] table names it)");
}

TEST_F(SignedCatalogue, ATruncatedSignatureIsRefused) {
    const fs::path dir = signed_catalogue("truncated", *chain_);
    const std::string whole = read_text(dir / "catalogue.toml.minisig");
    write_text(dir / "catalogue.toml.minisig", whole.substr(0, whole.size() / 2));
    const std::string line = verdict(dir, trusting({*chain_}));
    EXPECT_EQ(line.rfind("catalogue 'signed-truncated' rejected: catalogue.toml.minisig: ", 0), 0u)
        << line;
    EXPECT_NE(line.find("not a minisign signature"), std::string::npos) << line;
}

TEST_F(SignedCatalogue, ASignatureOverAnotherManifestIsRefused) {
    const fs::path dir = signed_catalogue("first", *chain_);
    const fs::path other = signed_catalogue("second", *chain_);
    fs::copy_file(other / "catalogue.toml.minisig", dir / "catalogue.toml.minisig",
                  fs::copy_options::overwrite_existing);
    EXPECT_EQ(verdict(dir, trusting({*chain_})),
              "catalogue 'signed-first' rejected: catalogue.toml.minisig: the signature by key " +
                  chain_->id +
                  " does not match (the file was changed after signing, or the signature is "
                  "another file's)");
}

TEST_F(SignedCatalogue, AChangedTrustedCommentIsRefused) {
    const fs::path dir = signed_catalogue("comment", *chain_);
    std::string text = read_text(dir / "catalogue.toml.minisig");
    // Line 3; line 1 is the *un*trusted comment.
    const std::size_t at =
        text.find("\ntrusted comment: ") + std::string("\ntrusted comment: ").size();
    text.insert(at, "x");
    write_text(dir / "catalogue.toml.minisig", text);
    EXPECT_EQ(verdict(dir, trusting({*chain_})),
              "catalogue 'signed-comment' rejected: catalogue.toml.minisig: the signature's "
              "trusted comment was changed after signing");
}

TEST_F(SignedCatalogue, WithoutAReadableKeyEveryDeliveryIsRefused) {
    const fs::path dir = signed_catalogue("nokey", *chain_);
    // The config listed a key whose file could not be read (config_fallback_test.cpp), or one
    // that is not a key.
    std::vector<std::string> problems;
    const CatalogueTrust trust = parse_trust(true, {{"chain.pub", "not a key\n"}}, problems);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0],
              "chain.pub: not a minisign public key (its key line must be 56 base64 "
              "characters)");
    EXPECT_TRUE(trust.required);
    EXPECT_EQ(verdict(dir, trust),
              "catalogue 'signed-nokey' rejected: catalogue.toml.minisig: signed by key " +
                  chain_->id +
                  ", but none of the trusted key files could be read (see the start-up log)");
}

TEST_F(SignedCatalogue, WithoutKeysTheDigestsStillFindDamage) {
    const fs::path dir = signed_catalogue("unkeyed", *chain_);
    EXPECT_EQ(verdict(dir, {}), "accepted");
    std::vector<std::uint8_t> bytes = read_bytes(dir / "stones" / "round.gemdb");
    bytes.back() ^= 0x01;
    write_bytes(dir / "stones" / "round.gemdb", bytes);
    EXPECT_NE(verdict(dir, {}).find("stones/round.gemdb: does not match its digest"),
              std::string::npos);
}

TEST_F(SignedCatalogue, ASignedManifestWithoutDigestsIsRefused) {
    const fs::path dir = fresh_dir("signed-nodigests");
    write_catalogue(dir, "nodigests");
    sign(dir / "catalogue.toml", *chain_);
    const std::string line = verdict(dir, trusting({*chain_}));
    EXPECT_NE(line.find("catalogue 'nodigests' rejected: catalogue.toml: names no file's digest"),
              std::string::npos)
        << line;
}

}  // namespace
}  // namespace gem::kiosk
