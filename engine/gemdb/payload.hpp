#pragma once
// The raw (uncompressed) payload of one view at one level (docs/gemdb-format.md, "Payload"):
// hit and ray counts, a coverage bitmask so missed pixels cost one bit, per-hit-pixel ray
// counts and truncated weights, then every ray field as its own array (structure of arrays
// compresses far better than interleaved records).

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gemdb/database_types.hpp"
#include "gemdb/quantise.hpp"
#include "trace/ray_list.hpp"
#include "util/result.hpp"

namespace gem {

struct PayloadCounts {
    std::uint32_t hits = 0;
    std::uint32_t rays = 0;
};

// Bytes of a raw payload with these counts; the reader checks sizes against it.
std::uint64_t payload_size(std::uint32_t side, PayloadCounts counts, bool derivatives);

// Encodes side² ray-lists (row-major) into `raw` (replaced). `derivatives`, when not null,
// holds d(direction)/dn for every exit ray of every hit pixel in order, before dropping.
// Exit rays lighter than `weight_threshold` are dropped and their weight is added to the
// pixel's truncated weight. Errors describe what is wrong with the input.
Result<PayloadCounts> encode_payload(std::span<const RayList> lists,
                                     const std::vector<glm::dvec3>* derivatives, std::uint32_t side,
                                     const PositionBox& box, double weight_threshold,
                                     std::vector<std::uint8_t>& raw);

// Decodes and validates a raw payload; errors describe the inconsistency.
Result<PayloadCounts> decode_payload(std::span<const std::uint8_t> raw, std::uint32_t side,
                                     bool derivatives, const PositionBox& box, DecodedView& out);

}  // namespace gem
