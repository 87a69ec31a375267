#include "gemdb/payload.hpp"

#include <bit>
#include <cmath>
#include <string>

namespace gem {

namespace {

constexpr std::uint64_t kPrefixBytes = 8;
constexpr std::uint64_t kRayBytes = 18;        // 9 fields × 2 bytes
constexpr std::uint64_t kDerivativeBytes = 6;  // 3 halves

void put16(std::uint8_t* base, std::size_t index, std::uint16_t v) {
    base[2 * index] = static_cast<std::uint8_t>(v);
    base[2 * index + 1] = static_cast<std::uint8_t>(v >> 8);
}

std::uint16_t get16(const std::uint8_t* base, std::size_t index) {
    return static_cast<std::uint16_t>(base[2 * index] | (base[2 * index + 1] << 8));
}

std::uint32_t get32(const std::uint8_t* p) {
    return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
           (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string pixel_name(std::size_t p, std::uint32_t side) {
    return "pixel (" + std::to_string(p % side) + ", " + std::to_string(p / side) + ")";
}

// Where each ray field array starts inside the raw payload.
struct Layout {
    std::uint64_t mask = kPrefixBytes;
    std::uint64_t counts = 0;
    std::uint64_t truncated = 0;
    std::uint64_t fields = 0;  // first of the per-ray arrays, each rays × 2 bytes
};

Layout layout(std::uint32_t side, std::uint32_t hits) {
    Layout l;
    const std::uint64_t pixels = static_cast<std::uint64_t>(side) * side;
    l.counts = l.mask + (pixels + 7) / 8;
    l.truncated = l.counts + 2ull * hits;
    l.fields = l.truncated + 2ull * hits;
    return l;
}

}  // namespace

std::uint64_t payload_size(std::uint32_t side, PayloadCounts counts, bool derivatives) {
    const std::uint64_t per_ray = kRayBytes + (derivatives ? kDerivativeBytes : 0);
    return layout(side, counts.hits).fields + per_ray * counts.rays;
}

Result<PayloadCounts> encode_payload(std::span<const RayList> lists,
                                     const std::vector<glm::dvec3>* derivatives, std::uint32_t side,
                                     const PositionBox& box, double weight_threshold,
                                     std::vector<std::uint8_t>& raw) {
    const std::size_t pixels = static_cast<std::size_t>(side) * side;
    if (lists.size() != pixels) {
        return Error{"got " + std::to_string(lists.size()) + " ray-lists, expected " +
                     std::to_string(pixels) + " (" + std::to_string(side) + "²)"};
    }
    PayloadCounts counts;
    std::size_t exits_seen = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        const RayList& list = lists[p];
        if (!list.hit) continue;
        std::uint64_t kept = 1;
        for (const TracedRay& ray : list.exits) kept += ray.weight >= weight_threshold ? 1 : 0;
        exits_seen += list.exits.size();
        if (kept > 0xFFFF) return Error{pixel_name(p, side) + " has more than 65535 rays"};
        ++counts.hits;
        counts.rays += static_cast<std::uint32_t>(kept);
    }
    if (derivatives != nullptr && derivatives->size() != exits_seen) {
        return Error{"got " + std::to_string(derivatives->size()) + " direction derivatives for " +
                     std::to_string(exits_seen) + " exit rays"};
    }
    const bool with_dn = derivatives != nullptr;
    const Layout l = layout(side, counts.hits);
    raw.assign(payload_size(side, counts, with_dn), 0);
    std::uint8_t* base = raw.data();
    for (int i = 0; i < 4; ++i) {
        base[i] = static_cast<std::uint8_t>(counts.hits >> (8 * i));
        base[4 + i] = static_cast<std::uint8_t>(counts.rays >> (8 * i));
    }
    std::uint8_t* field[12] = {};
    for (int f = 0; f < (with_dn ? 12 : 9); ++f)
        field[f] = base + l.fields + 2ull * counts.rays * f;
    std::size_t hit = 0;
    std::size_t ray = 0;
    std::size_t exit_index = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        const RayList& list = lists[p];
        if (!list.hit) continue;
        base[l.mask + p / 8] |= static_cast<std::uint8_t>(1u << (p % 8));
        const std::size_t first = ray;
        double dropped = 0.0;
        auto emit = [&](const TracedRay& r, const glm::dvec3& dn) -> bool {
            if (!finite(r.origin) || !finite(r.direction) || !finite(dn) ||
                !std::isfinite(r.weight) || !std::isfinite(r.path_mm) ||
                glm::length(r.direction) < 0.5 || r.facet > 0xFFFF) {
                return false;
            }
            const OctCode oct = encode_octahedral(r.direction);
            const PositionCode pos = encode_position(r.origin, box);
            put16(field[0], ray, oct.u);
            put16(field[1], ray, oct.v);
            put16(field[2], ray, double_to_half(r.weight));
            put16(field[3], ray, double_to_half(r.path_mm));
            put16(field[4], ray, pos.x);
            put16(field[5], ray, pos.y);
            put16(field[6], ray, pos.z);
            put16(field[7], ray, r.bounces);
            put16(field[8], ray, static_cast<std::uint16_t>(r.facet));
            if (with_dn) {
                put16(field[9], ray, double_to_half(dn.x));
                put16(field[10], ray, double_to_half(dn.y));
                put16(field[11], ray, double_to_half(dn.z));
            }
            ++ray;
            return true;
        };
        // Reflection does not depend on the refractive index, so its derivative is zero.
        bool good = emit(list.reflected, glm::dvec3(0.0));
        for (const TracedRay& r : list.exits) {
            const glm::dvec3 dn = with_dn ? (*derivatives)[exit_index] : glm::dvec3(0.0);
            ++exit_index;
            if (r.weight < weight_threshold) {
                dropped += r.weight;
                continue;
            }
            good = good && emit(r, dn);
        }
        if (!good) {
            return Error{pixel_name(p, side) +
                         " has a ray with a non-finite field, a zero direction or a facet "
                         "number above 65535"};
        }
        put16(base + l.counts, hit, static_cast<std::uint16_t>(ray - first));
        put16(base + l.truncated, hit, double_to_half(list.truncated_weight + dropped));
        ++hit;
    }
    return counts;
}

Result<PayloadCounts> decode_payload(std::span<const std::uint8_t> raw, std::uint32_t side,
                                     bool derivatives, const PositionBox& box, DecodedView& out) {
    if (raw.size() < kPrefixBytes) return Error{"payload shorter than its counts"};
    const PayloadCounts counts{get32(raw.data()), get32(raw.data() + 4)};
    const std::uint64_t pixels = static_cast<std::uint64_t>(side) * side;
    if (counts.hits > pixels || counts.rays < counts.hits) {
        return Error{"payload counts are impossible (" + std::to_string(counts.hits) +
                     " hit pixels, " + std::to_string(counts.rays) + " rays)"};
    }
    if (payload_size(side, counts, derivatives) != raw.size()) {
        return Error{"payload size does not match its counts"};
    }
    const Layout l = layout(side, counts.hits);
    const std::uint8_t* base = raw.data();
    std::uint64_t set_bits = 0;
    for (std::uint64_t b = 0; b < (pixels + 7) / 8; ++b)
        set_bits += std::popcount(base[l.mask + b]);
    const unsigned tail = static_cast<unsigned>(pixels % 8);
    if (set_bits != counts.hits || (tail != 0 && (base[l.mask + pixels / 8] >> tail) != 0)) {
        return Error{"payload coverage mask does not match its hit count"};
    }
    std::uint64_t total = 0;
    for (std::uint32_t h = 0; h < counts.hits; ++h) {
        const std::uint16_t n = get16(base + l.counts, h);
        if (n == 0) return Error{"payload has a hit pixel without rays"};
        total += n;
    }
    if (total != counts.rays) return Error{"payload ray counts do not add up"};

    out.side = side;
    out.ray_offset.assign(pixels, 0);
    out.ray_count.assign(pixels, 0);
    out.truncated_weight.assign(pixels, 0.0f);
    std::uint32_t hit = 0;
    std::uint32_t next = 0;
    for (std::uint64_t p = 0; p < pixels; ++p) {
        out.ray_offset[p] = next;
        if (((base[l.mask + p / 8] >> (p % 8)) & 1u) == 0) continue;
        out.ray_count[p] = get16(base + l.counts, hit);
        out.truncated_weight[p] = half_to_float(get16(base + l.truncated, hit));
        next += out.ray_count[p];
        ++hit;
    }
    const std::size_t n = counts.rays;
    const std::uint8_t* field[12] = {};
    for (int f = 0; f < (derivatives ? 12 : 9); ++f) field[f] = base + l.fields + 2ull * n * f;
    out.direction.resize(n);
    out.weight.resize(n);
    out.path_mm.resize(n);
    out.position.resize(n);
    out.bounces.resize(n);
    out.facet.resize(n);
    out.dir_dn.resize(derivatives ? n : 0);
    for (std::size_t r = 0; r < n; ++r) {
        out.direction[r] = glm::vec3(decode_octahedral({get16(field[0], r), get16(field[1], r)}));
        out.weight[r] = half_to_float(get16(field[2], r));
        out.path_mm[r] = half_to_float(get16(field[3], r));
        out.position[r] = glm::vec3(
            decode_position({get16(field[4], r), get16(field[5], r), get16(field[6], r)}, box));
        out.bounces[r] = get16(field[7], r);
        out.facet[r] = get16(field[8], r);
        if (derivatives) {
            out.dir_dn[r] = {half_to_float(get16(field[9], r)), half_to_float(get16(field[10], r)),
                             half_to_float(get16(field[11], r))};
        }
    }
    return counts;
}

}  // namespace gem
