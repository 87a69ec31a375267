#pragma once
// Fixed facts of the .gemdb container (docs/gemdb-format.md, "File layout"): magic, version,
// header and index record sizes, section identifiers and the sanity limits the reader checks
// every count against before it allocates or indexes anything.

#include <array>
#include <cstdint>

namespace gem::gemdb {

// Like PNG's signature: a high-bit byte catches 7-bit transfers, CR LF catches line-ending
// conversion either way, ^Z stops a DOS `type`, the final LF catches LF → CR LF.
inline constexpr std::array<std::uint8_t, 8> kMagic{0x89, 'G', 'E', 'M', '\r', '\n', 0x1A, '\n'};

// Major: incompatible layout, refused by older readers. Minor: additions an older reader of
// the same major may ignore (new sections, which it skips).
inline constexpr std::uint16_t kVersionMajor = 1;
inline constexpr std::uint16_t kVersionMinor = 0;

inline constexpr std::uint32_t kFlagDerivatives = 1u;  // rays carry d(direction)/dn
inline constexpr std::uint32_t kKnownFlags = kFlagDerivatives;

inline constexpr std::uint32_t kHeaderFixedBytes = 48;
inline constexpr std::uint32_t kSectionRecordBytes = 32;
inline constexpr std::uint32_t kIndexRecordBytes = 32;

enum class SectionId : std::uint32_t {
    stone = 1,
    material = 2,
    camera = 3,
    params = 4,
    grid = 5,
    index = 6,
};
inline constexpr std::uint32_t kRequiredSections = 6;

// Sanity limits: far above any real database, low enough that a damaged count cannot make
// the reader allocate gigabytes.
inline constexpr std::uint32_t kMaxSections = 64;
inline constexpr std::uint32_t kMaxViews = 1u << 22;
inline constexpr std::uint32_t kMaxLevels = 16;
inline constexpr std::uint32_t kMaxSide = 8192;
inline constexpr std::uint32_t kMaxVertices = 1u << 20;
inline constexpr std::uint32_t kMaxFacets = 0xFFFF;  // facet numbers are stored in 16 bits
inline constexpr std::uint32_t kMaxTriangles = 1u << 22;
inline constexpr std::uint32_t kMaxSymmetry = 256;
inline constexpr std::uint32_t kMaxCoefficients = 16;
inline constexpr std::uint64_t kMaxRawPayload = 1ull << 32;

}  // namespace gem::gemdb
