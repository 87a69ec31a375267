// Damaged databases: every flipped bit, truncation, wrong signature, future version and absurd
// count or offset gives one error naming the file and the fault, never a crash (run these
// under -DGEM_SANITIZE=ON to check that no read goes out of bounds).

#include <gtest/gtest.h>
#include <xxhash.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "gemdb/reader.hpp"
#include "tables_test_support.hpp"

namespace gem {
namespace {

using namespace tables_test;

// Layout facts from docs/gemdb-format.md, written out here rather than taken from format.hpp.
constexpr std::size_t kSectionCount = 6;
constexpr std::size_t kHeaderBytes = 48 + kSectionCount * 32 + 8;

std::uint64_t get_u64(const std::vector<std::uint8_t>& b, std::size_t at) {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(b[at + i]) << (8 * i);
    return v;
}

void put_u64(std::vector<std::uint8_t>& b, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

void put_u32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::size_t section_offset(const std::vector<std::uint8_t>& b, std::size_t s) {
    return get_u64(b, 48 + 32 * s + 8);
}
std::size_t section_size(const std::vector<std::uint8_t>& b, std::size_t s) {
    return get_u64(b, 48 + 32 * s + 16);
}

// Re-seals a deliberately edited file so that only the edit, not a checksum, is wrong.
void reseal_section(std::vector<std::uint8_t>& b, std::size_t s) {
    put_u64(b, 48 + 32 * s + 24, XXH64(b.data() + section_offset(b, s), section_size(b, s), 0));
}
void reseal_header(std::vector<std::uint8_t>& b) {
    put_u64(b, kHeaderBytes - 8, XXH64(b.data(), kHeaderBytes - 8, 0));
}

class TablesDamage : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = new std::filesystem::path(artifact_dir("damage"));
        original_ = new std::vector<std::uint8_t>();
        SmallDatabase db = small_database(true);
        db.params.levels = {6, 12};
        ASSERT_TRUE(write_small(*dir_ / "good.gemdb", db).ok());
        *original_ = read_bytes(*dir_ / "good.gemdb");
    }
    static void TearDownTestSuite() {
        delete dir_;
        delete original_;
    }

    // Writes `bytes` and expects open() to fail with the file's name and `fault` in the message.
    static void expect_refused(const std::vector<std::uint8_t>& bytes, const std::string& fault,
                               const std::string& what) {
        const auto path = *dir_ / "damaged.gemdb";
        write_bytes(path, bytes);
        auto db = Database::open(path);
        ASSERT_FALSE(db.ok()) << what << " was accepted";
        EXPECT_NE(db.error().find(path.string()), std::string::npos) << db.error();
        EXPECT_NE(db.error().find(fault), std::string::npos) << what << ": " << db.error();
    }

    static std::filesystem::path* dir_;
    static std::vector<std::uint8_t>* original_;
};

std::filesystem::path* TablesDamage::dir_ = nullptr;
std::vector<std::uint8_t>* TablesDamage::original_ = nullptr;

TEST_F(TablesDamage, IntactFileOpensAndDecodes) {
    auto db = Database::open(*dir_ / "good.gemdb");
    ASSERT_TRUE(db.ok()) << db.error();
    for (std::uint32_t v = 0; v < db.value().view_count(); ++v) {
        EXPECT_TRUE(db.value().decode(v, 1).ok());
    }
    auto none = db.value().decode(db.value().view_count(), 0);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().find("does not exist"), std::string::npos);
}

TEST_F(TablesDamage, EveryFlippedBitBeforeThePayloadsIsRefused) {
    const std::vector<std::uint8_t>& good = *original_;
    const std::size_t payloads = section_offset(good, 5) + section_size(good, 5);
    // Every byte of the header, then a spread of bytes through the sections and the index.
    for (std::size_t at = 0; at < payloads; at += (at < kHeaderBytes ? 1 : 13)) {
        std::vector<std::uint8_t> bad = good;
        bad[at] ^= static_cast<std::uint8_t>(1u << (at % 8));
        // Which message depends on where the bit is; that there is one naming the file is
        // what is checked here.
        expect_refused(bad, ": ", "bit flip at byte " + std::to_string(at));
        if (HasFatalFailure()) return;
    }
}

TEST_F(TablesDamage, FlippedBitInEachSectionNamesTheSection) {
    const char* names[] = {"stone", "material", "camera", "params", "grid", "index"};
    for (std::size_t s = 0; s < kSectionCount; ++s) {
        std::vector<std::uint8_t> bad = *original_;
        bad[section_offset(bad, s) + section_size(bad, s) / 2] ^= 0x10;
        expect_refused(bad, std::string("section ") + names[s] + " checksum mismatch", names[s]);
    }
    std::vector<std::uint8_t> bad = *original_;
    bad[20] ^= 0x04;  // inside the header's section count
    expect_refused(bad, "header", "header bit");
}

TEST_F(TablesDamage, FlippedBitInAPayloadFailsThatViewOnly) {
    const std::vector<std::uint8_t>& good = *original_;
    const std::size_t payloads = section_offset(good, 5) + section_size(good, 5);
    const auto path = *dir_ / "payload.gemdb";
    int refused = 0;
    for (std::size_t at = payloads; at < good.size(); at += 499) {
        std::vector<std::uint8_t> bad = good;
        bad[at] ^= 0x01;
        write_bytes(path, bad);
        auto db = Database::open(path);
        ASSERT_TRUE(db.ok()) << "payloads are checked on decode, not on open: " << db.error();
        int failing = 0;
        for (std::uint32_t v = 0; v < db.value().view_count(); ++v) {
            for (std::uint32_t l = 0; l < db.value().level_count(); ++l) {
                auto view = db.value().decode(v, l);
                if (view.ok()) continue;
                ++failing;
                EXPECT_NE(view.error().find(path.string()), std::string::npos);
                EXPECT_NE(view.error().find("checksum mismatch"), std::string::npos)
                    << view.error();
            }
        }
        EXPECT_EQ(failing, 1) << "byte " << at;
        ++refused;
    }
    EXPECT_GT(refused, 10);
}

TEST_F(TablesDamage, TruncationAtAnyLengthIsRefused) {
    const std::vector<std::uint8_t>& good = *original_;
    for (std::size_t length = 0; length < good.size(); length += (length < 300 ? 3 : 211)) {
        const std::vector<std::uint8_t> cut(good.begin(),
                                            good.begin() + static_cast<std::ptrdiff_t>(length));
        const std::string fault = length < 48 ? "too short" : "truncated";
        expect_refused(cut, fault, "truncated to " + std::to_string(length));
        if (HasFatalFailure()) return;
    }
    std::vector<std::uint8_t> longer = good;
    longer.push_back(0);
    expect_refused(longer, "after its end", "one extra byte");
}

TEST_F(TablesDamage, SignatureDamageIsDiagnosed) {
    std::vector<std::uint8_t> png = *original_;
    std::memcpy(png.data(), "\x89PNG\r\n\x1a\n", 8);
    expect_refused(png, "wrong magic", "PNG signature");
    std::vector<std::uint8_t> seven_bit = *original_;
    seven_bit[0] = 0x09;
    expect_refused(seven_bit, "high bit", "7-bit transfer");
    std::vector<std::uint8_t> dos = *original_;
    dos.erase(dos.begin() + 4);  // CR LF → LF, as a text-mode copy would
    expect_refused(dos, "line endings", "CR LF → LF");
    std::vector<std::uint8_t> unix_to_dos = *original_;
    unix_to_dos.insert(unix_to_dos.begin() + 7, '\r');  // final LF → CR LF
    expect_refused(unix_to_dos, "line endings", "LF → CR LF");
}

TEST_F(TablesDamage, FutureVersionIsRefusedWithAMessageSayingSo) {
    std::vector<std::uint8_t> future = *original_;
    future[8] = 2;  // major version 2, minor 0
    reseal_header(future);
    expect_refused(future, "format version 2.0 is newer than this build reads", "version 2.0");
    std::vector<std::uint8_t> zero = *original_;
    zero[8] = 0;
    reseal_header(zero);
    expect_refused(zero, "unknown format version 0.0", "version 0.0");
}

TEST_F(TablesDamage, AbsurdCountsAndOffsetsAreRefused) {
    {
        std::vector<std::uint8_t> bad = *original_;
        put_u32(bad, 32, 0xFFFFFFFFu);  // view count
        reseal_header(bad);
        expect_refused(bad, "view count 4294967295 is absurd", "view count");
    }
    {
        std::vector<std::uint8_t> bad = *original_;
        put_u32(bad, 36, 1000);  // level count
        reseal_header(bad);
        expect_refused(bad, "level count 1000 is absurd", "level count");
    }
    {
        std::vector<std::uint8_t> bad = *original_;
        put_u64(bad, 48 + 32 * 2 + 8, 1ull << 60);  // camera section offset
        reseal_header(bad);
        expect_refused(bad, "section camera lies outside the file", "section offset");
    }
    {
        std::vector<std::uint8_t> bad = *original_;
        put_u64(bad, 48 + 32 * 3 + 16, 1ull << 40);  // params section size
        reseal_header(bad);
        expect_refused(bad, "section params lies outside the file", "section size");
    }
    {
        std::vector<std::uint8_t> bad = *original_;
        // The stone section starts with its name (u32 length + bytes), then the vertex count.
        const std::size_t stone = section_offset(bad, 0);
        const std::size_t name = bad[stone] | (bad[stone + 1] << 8);
        put_u32(bad, stone + 4 + name, 0x7FFFFFFFu);
        reseal_section(bad, 0);
        reseal_header(bad);
        expect_refused(bad, "vertex count 2147483647 is absurd", "vertex count");
    }
    {
        std::vector<std::uint8_t> bad = *original_;
        put_u32(bad, section_offset(bad, 0), 0xFFFFFFF0u);  // stone name length
        reseal_section(bad, 0);
        reseal_header(bad);
        expect_refused(bad, "stone section is truncated or has a bad length", "name length");
    }
    {
        std::vector<std::uint8_t> bad = *original_;
        put_u64(bad, section_offset(bad, 5) + 32, 12345);  // second payload's offset
        reseal_section(bad, 5);
        reseal_header(bad);
        expect_refused(bad, "index entry for view 0 level 1 points outside the file",
                       "payload offset");
    }
    {
        std::vector<std::uint8_t> bad = *original_;
        put_u32(bad, section_offset(bad, 5) + 12, 0xFFFFFFFFu);  // first payload's raw size
        reseal_section(bad, 5);
        reseal_header(bad);
        expect_refused(bad, "impossible sizes or counts", "raw size");
    }
    {
        std::vector<std::uint8_t> bad = *original_;
        put_u32(bad, 12, 0x80);  // an unknown flag
        reseal_header(bad);
        expect_refused(bad, "unknown flags 0x80", "flags");
    }
}

TEST_F(TablesDamage, MissingAndNonFilesAreErrors) {
    auto missing = Database::open(*dir_ / "missing.gemdb");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("missing.gemdb: cannot open"), std::string::npos);
    auto directory = Database::open(*dir_);
    ASSERT_FALSE(directory.ok());
    EXPECT_NE(directory.error().find("not a regular file"), std::string::npos);
}

// The writer refuses coefficients that do not fit their kind, so the file is written with a
// fitting count and only the kind byte is changed afterwards.
TEST_F(TablesDamage, CoefficientsThatDoNotFitTheDispersionKindAreRefused) {
    struct Case {
        Dispersion::Kind written;
        std::vector<double> coef;
        Dispersion::Kind patched;
    };
    const std::vector<Case> cases = {
        {Dispersion::Kind::constant, {1.76}, Dispersion::Kind::cauchy},
        {Dispersion::Kind::constant, {1.76}, Dispersion::Kind::sellmeier},
        {Dispersion::Kind::cauchy, {1.7, 0.006, 0.0001}, Dispersion::Kind::sellmeier},
    };
    for (const Case& c : cases) {
        SmallDatabase db = small_database(false);
        db.stone.material.dispersion.kind = c.written;
        db.stone.material.dispersion.coef = c.coef;
        const auto path = *dir_ / "material.gemdb";
        ASSERT_TRUE(write_small(path, db).ok());
        std::vector<std::uint8_t> bad = read_bytes(path);
        ASSERT_TRUE(Database::open(path).ok()) << "the unpatched file must open";
        // The material section starts with its name (u32 length + bytes), then the kind byte.
        const std::size_t material = section_offset(bad, 1);
        const std::size_t name = bad[material] | (bad[material + 1] << 8);
        ASSERT_EQ(bad[material + 4 + name], static_cast<std::uint8_t>(c.written));
        bad[material + 4 + name] = static_cast<std::uint8_t>(c.patched);
        reseal_section(bad, 1);
        reseal_header(bad);
        expect_refused(bad,
                       "material section: " + std::to_string(c.coef.size()) +
                           " coefficients do not fit the dispersion kind",
                       "kind " + std::to_string(int(c.patched)));
    }
}

// A file whose stone has one facet fewer than its rays name: written with a seven-facet stone
// whose rays name facet 6, then given the stone section of the six-facet stone it was made
// from. The stone names are padded so that both sections have the same size, so only the
// stone section and the checksums change.
TEST_F(TablesDamage, ARayNamingAMissingFacetFailsThatViewOnly) {
    SmallDatabase six = small_database(false);
    SmallDatabase seven = six;
    Facet extra = seven.stone.facets[0];
    extra.name = "face 6";
    seven.stone.facets.push_back(extra);
    const auto seven_path = *dir_ / "seven.gemdb";
    const auto six_path = *dir_ / "six.gemdb";
    auto written = write_database(seven_path, seven.stone, seven.camera, seven.params, seven.grid,
                                  [&](std::uint32_t view, std::uint32_t level) {
                                      std::vector<RayList> lists = random_lists(
                                          chunk_seed(view, level), seven.params.levels[level]);
                                      if (view == 0 && level == 0) {
                                          for (RayList& list : lists) {
                                              if (!list.hit) continue;
                                              list.reflected.facet = 6;
                                              break;
                                          }
                                      }
                                      return lists;
                                  });
    ASSERT_TRUE(written.ok()) << written.error();
    const std::vector<std::uint8_t> with_seven = read_bytes(seven_path);
    ASSERT_TRUE(write_small(six_path, six).ok());
    const std::size_t grow = section_size(with_seven, 0) - section_size(read_bytes(six_path), 0);
    six.stone.name += std::string(grow, '.');
    ASSERT_TRUE(write_small(six_path, six).ok());
    const std::vector<std::uint8_t> with_six = read_bytes(six_path);
    ASSERT_EQ(section_size(with_six, 0), section_size(with_seven, 0));
    ASSERT_EQ(section_offset(with_six, 0), section_offset(with_seven, 0));

    {
        auto good = Database::open(seven_path);
        ASSERT_TRUE(good.ok()) << good.error();
        ASSERT_TRUE(good.value().decode(0, 0).ok()) << "facet 6 exists in the seven-facet stone";
    }
    std::vector<std::uint8_t> bad = with_seven;
    const std::size_t stone = section_offset(bad, 0);
    std::copy_n(with_six.begin() + static_cast<std::ptrdiff_t>(stone), section_size(bad, 0),
                bad.begin() + static_cast<std::ptrdiff_t>(stone));
    reseal_section(bad, 0);
    reseal_header(bad);
    const auto path = *dir_ / "missing-facet.gemdb";
    write_bytes(path, bad);
    auto db = Database::open(path);
    ASSERT_TRUE(db.ok()) << "payloads are checked on decode, not on open: " << db.error();
    ASSERT_EQ(db.value().stone().facets.size(), 6u);
    for (std::uint32_t v = 0; v < db.value().view_count(); ++v) {
        for (std::uint32_t l = 0; l < db.value().level_count(); ++l) {
            auto view = db.value().decode(v, l);
            if (v == 0 && l == 0) {
                ASSERT_FALSE(view.ok());
                EXPECT_NE(view.error().find(path.string()), std::string::npos) << view.error();
                EXPECT_NE(view.error().find("a ray names facet 6 of a stone with 6"),
                          std::string::npos)
                    << view.error();
            } else {
                EXPECT_TRUE(view.ok()) << "view " << v << " level " << l << ": " << view.error();
            }
        }
    }
}

}  // namespace
}  // namespace gem
