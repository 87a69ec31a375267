// libFuzzer target: any bytes handed to Database::open, and every view of what it accepts
// decoded. The reader must answer each input with a database or an Error, never a crash,
// a sanitizer report, an assertion or a runaway allocation.
//
// Every byte of a .gemdb is covered by an xxHash64 checksum, so almost every mutation would
// stop at a checksum mismatch. Before opening, the harness therefore re-seals what it can of
// the mutated input (docs/gemdb-format.md, "File layout"): each payload checksum in the
// index section, then each section's checksum in the section table, then the header
// checksum, so that mutations reach the section parsers and the payload decoder.
#include <unistd.h>
#include <xxhash.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "gemdb/format.hpp"
#include "gemdb/reader.hpp"

namespace {

// The reader maps files, and offers no path from memory, so each input goes through one
// file per process.
const std::filesystem::path& input_path() {
    static const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("gem_fuzz_gemdb_" + std::to_string(::getpid()) + ".gemdb");
    return path;
}

std::uint64_t get_le(const std::vector<std::uint8_t>& b, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(b[at + i]) << (8 * i);
    return v;
}

void put_u64(std::vector<std::uint8_t>& b, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

// True when [offset, offset + size) lies inside b.
bool inside(const std::vector<std::uint8_t>& b, std::uint64_t offset, std::uint64_t size) {
    return offset <= b.size() && size <= b.size() - offset;
}

// Re-seals every checksum whose range the (possibly damaged) header and index describe
// inside the input; anything that points outside is left for the reader to refuse.
void reseal(std::vector<std::uint8_t>& b) {
    namespace f = gem::gemdb;
    if (b.size() < f::kHeaderFixedBytes + 8) return;
    const std::uint64_t header_bytes = get_le(b, 16, 4);
    const std::uint64_t sections = get_le(b, 20, 4);
    if (sections > f::kMaxSections) return;
    const std::uint64_t table_end = f::kHeaderFixedBytes + f::kSectionRecordBytes * sections;
    if (header_bytes != table_end + 8 || header_bytes > b.size()) return;

    // Payloads first: their checksums live in the index section.
    for (std::uint64_t s = 0; s < sections; ++s) {
        const std::size_t rec = f::kHeaderFixedBytes + f::kSectionRecordBytes * s;
        if (get_le(b, rec, 4) != static_cast<std::uint32_t>(f::SectionId::index)) continue;
        const std::uint64_t offset = get_le(b, rec + 8, 8);
        const std::uint64_t size = get_le(b, rec + 16, 8);
        if (!inside(b, offset, size)) continue;
        for (std::uint64_t e = 0; e + f::kIndexRecordBytes <= size; e += f::kIndexRecordBytes) {
            const std::size_t at = offset + e;
            const std::uint64_t payload = get_le(b, at, 8);
            const std::uint64_t compressed = get_le(b, at + 8, 4);
            if (!inside(b, payload, compressed)) continue;
            put_u64(b, at + 16, XXH64(b.data() + payload, compressed, 0));
        }
    }
    for (std::uint64_t s = 0; s < sections; ++s) {
        const std::size_t rec = f::kHeaderFixedBytes + f::kSectionRecordBytes * s;
        const std::uint64_t offset = get_le(b, rec + 8, 8);
        const std::uint64_t size = get_le(b, rec + 16, 8);
        if (!inside(b, offset, size)) continue;
        put_u64(b, rec + 24, XXH64(b.data() + offset, size, 0));
    }
    put_u64(b, header_bytes - 8, XXH64(b.data(), header_bytes - 8, 0));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::uint8_t> bytes(data, data + size);
    reseal(bytes);

    const std::filesystem::path& path = input_path();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) return 0;
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    std::fclose(f);
    if (!written) return 0;

    gem::Result<gem::Database> db = gem::Database::open(path);
    if (!db) return 0;
    const gem::Database& d = db.value();
    volatile double n = d.material().index();
    (void)n;
    const std::size_t facets = d.stone().facets.size();
    // Bounded, so one accepted input with a huge grid cannot stall the run.
    std::uint32_t decoded = 0;
    for (std::uint32_t v = 0; v < d.view_count() && decoded < 64; ++v) {
        for (std::uint32_t l = 0; l < d.level_count(); ++l, ++decoded) {
            gem::Result<gem::DecodedView> view = d.decode(v, l);
            if (!view.ok()) continue;
            const auto& x = view.value();
            if (!x.ray_count.empty()) {
                // Touch the last ray the offsets claim, so a bad offset shows under ASan.
                const std::size_t last = x.ray_count.size() - 1;
                if (x.ray_count[last] > 0) {
                    volatile float w = x.weight[x.ray_offset[last] + x.ray_count[last] - 1];
                    (void)w;
                }
            }
            // A decoded facet number must name a facet of the stone.
            for (std::uint16_t facet : x.facet) {
                if (facet >= facets) {
                    std::fprintf(stderr, "view %u level %u: facet %u of %zu facets\n", v, l,
                                 static_cast<unsigned>(facet), facets);
                    __builtin_trap();
                }
            }
        }
    }
    (void)d.grid().nearest(glm::dvec3(0.3, 0.8, -0.5));
    return 0;
}
