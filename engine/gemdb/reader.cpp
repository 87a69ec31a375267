#include "gemdb/reader.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xxhash.h>
#include <zstd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <span>
#include <string>

#include "gemdb/bytes.hpp"
#include "gemdb/format.hpp"
#include "gemdb/payload.hpp"
#include "gemdb/sections.hpp"

namespace gem {

struct Database::Mapping {
    const std::uint8_t* data = nullptr;
    std::size_t size = 0;
    Mapping(const std::uint8_t* d, std::size_t s) : data(d), size(s) {}
    Mapping(const Mapping&) = delete;
    Mapping& operator=(const Mapping&) = delete;
    ~Mapping() { ::munmap(const_cast<std::uint8_t*>(data), size); }
};

namespace {

constexpr const char* kSectionNames[] = {"",       "stone", "material", "camera",
                                         "params", "grid",  "index"};

// Says what kind of damage a wrong signature shows, as PNG's signature was designed to.
std::string diagnose_magic(std::span<const std::uint8_t> head) {
    const auto& m = gemdb::kMagic;
    if (std::equal(head.begin() + 1, head.begin() + 4, m.begin() + 1)) {
        if (head[0] == (m[0] & 0x7F))
            return "the high bit of the first byte was stripped (7-bit transfer)";
        if (head[0] == m[0])
            return "the signature's line endings were converted (text-mode transfer)";
    }
    return "not a gemdb database (wrong magic)";
}

std::string hex(std::uint64_t v) {
    char text[24];
    std::snprintf(text, sizeof text, "0x%llx", static_cast<unsigned long long>(v));
    return text;
}

}  // namespace

Result<Database> Database::open(const std::filesystem::path& path) {
    auto fail = [&](const std::string& what) { return Error{path.string() + ": " + what}; };
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return fail(std::string("cannot open: ") + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return fail("not a regular file");
    }
    const auto size = static_cast<std::size_t>(st.st_size);
    if (size < gemdb::kHeaderFixedBytes) {
        ::close(fd);
        return fail("too short to be a gemdb database (" + std::to_string(size) + " bytes)");
    }
    void* addr = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    const int map_errno = errno;
    ::close(fd);
    if (addr == MAP_FAILED) return fail(std::string("cannot map: ") + std::strerror(map_errno));

    Database db;
    db.path_ = path;
    db.map_ = std::make_shared<const Mapping>(static_cast<const std::uint8_t*>(addr), size);
    const std::span<const std::uint8_t> file(db.map_->data, size);

    if (!std::equal(gemdb::kMagic.begin(), gemdb::kMagic.end(), file.begin())) {
        return fail(diagnose_magic(file.first(8)));
    }
    // The version sits at the same place in every format version, so it is read before
    // anything whose layout a newer version could have changed.
    ByteReader h(file);
    h.take(8);
    const std::uint16_t major = h.u16();
    const std::uint16_t minor = h.u16();
    const std::string version = std::to_string(major) + "." + std::to_string(minor);
    if (major > gemdb::kVersionMajor) {
        return fail("format version " + version + " is newer than this build reads (" +
                    std::to_string(gemdb::kVersionMajor) + ".x); update gemkiosk");
    }
    if (major != gemdb::kVersionMajor) return fail("unknown format version " + version);
    db.version_minor_ = minor;
    const std::uint32_t flags = h.u32();
    const std::uint32_t header_bytes = h.u32();
    const std::uint32_t section_count = h.u32();
    const std::uint64_t file_bytes = h.u64();
    const std::uint32_t views = h.u32();
    const std::uint32_t levels = h.u32();
    h.u64();
    if (section_count == 0 || section_count > gemdb::kMaxSections) {
        return fail("header: section count " + std::to_string(section_count) + " is absurd");
    }
    if (header_bytes != gemdb::kHeaderFixedBytes + section_count * gemdb::kSectionRecordBytes + 8) {
        return fail("header: size " + std::to_string(header_bytes) + " does not match its " +
                    std::to_string(section_count) + " sections");
    }
    if (header_bytes > size) {
        return fail("truncated inside the header (" + std::to_string(size) + " bytes)");
    }
    ByteReader tail(file.subspan(header_bytes - 8, 8));
    if (XXH64(file.data(), header_bytes - 8, 0) != tail.u64()) {
        return fail("header checksum mismatch (damaged header)");
    }
    if (file_bytes != size) {
        return fail(size < file_bytes
                        ? "truncated: " + std::to_string(size) + " of " +
                              std::to_string(file_bytes) + " bytes"
                        : "has " + std::to_string(size - file_bytes) + " bytes after its end");
    }
    if ((flags & ~gemdb::kKnownFlags) != 0) return fail("header: unknown flags " + hex(flags));
    if (views == 0 || views > gemdb::kMaxViews) {
        return fail("header: view count " + std::to_string(views) + " is absurd");
    }
    if (levels == 0 || levels > gemdb::kMaxLevels) {
        return fail("header: level count " + std::to_string(levels) + " is absurd");
    }

    // Sections lie back to back after the header; each is checked before it is parsed.
    std::array<std::span<const std::uint8_t>, gemdb::kRequiredSections + 1> found{};
    std::array<bool, gemdb::kRequiredSections + 1> seen{};
    std::uint64_t at = header_bytes;
    for (std::uint32_t s = 0; s < section_count; ++s) {
        const std::uint32_t id = h.u32();
        h.u32();
        const std::uint64_t offset = h.u64();
        const std::uint64_t bytes = h.u64();
        const std::uint64_t checksum = h.u64();
        const std::string name = id >= 1 && id <= gemdb::kRequiredSections
                                     ? kSectionNames[id]
                                     : "#" + std::to_string(id);
        if (offset != at || bytes > size - offset) {
            return fail("section " + name + " lies outside the file or out of order (offset " +
                        std::to_string(offset) + ", " + std::to_string(bytes) + " bytes)");
        }
        const auto span = file.subspan(offset, bytes);
        if (XXH64(span.data(), span.size(), 0) != checksum) {
            return fail("section " + name + " checksum mismatch (damaged)");
        }
        at += bytes;
        if (id < 1 || id > gemdb::kRequiredSections) continue;  // a later minor's addition
        if (seen[id]) return fail("section " + name + " appears twice");
        seen[id] = true;
        found[id] = span;
    }
    for (std::uint32_t id = 1; id <= gemdb::kRequiredSections; ++id) {
        if (!seen[id]) return fail(std::string("section ") + kSectionNames[id] + " is missing");
    }

    auto stone = read_stone_section(found[1]);
    if (!stone) return fail(stone.error());
    db.stone_ = std::move(stone.value());
    auto material = read_material_section(found[2]);
    if (!material) return fail(material.error());
    db.stone_.material = std::move(material.value());
    auto camera = read_camera_section(found[3]);
    if (!camera) return fail(camera.error());
    db.camera_ = camera.value();
    auto params = read_params_section(found[4]);
    if (!params) return fail(params.error());
    db.params_ = std::move(params.value().params);
    db.box_ = params.value().box;
    auto grid = read_grid_section(found[5], db.stone_.symmetry);
    if (!grid) return fail(grid.error());
    db.grid_ = std::move(grid.value());
    if (db.params_.levels.size() != levels || db.grid_.size() != views) {
        return fail("header counts (" + std::to_string(views) + " views, " +
                    std::to_string(levels) + " levels) disagree with the params and grid sections");
    }
    if (db.grid_.spec().spacing_rad != db.params_.grid.spacing_rad ||
        db.grid_.spec().min_elevation_rad != db.params_.grid.min_elevation_rad) {
        return fail("grid and params sections disagree about the view grid");
    }
    const bool derivatives = (flags & gemdb::kFlagDerivatives) != 0;
    if (derivatives != db.params_.dispersion) {
        return fail("header flags and params section disagree about dispersion");
    }

    // The index: payloads follow the sections back to back and end the file.
    const std::uint64_t entries = static_cast<std::uint64_t>(views) * levels;
    if (found[6].size() != entries * gemdb::kIndexRecordBytes) {
        return fail("index section has " + std::to_string(found[6].size()) + " bytes, expected " +
                    std::to_string(entries * gemdb::kIndexRecordBytes));
    }
    ByteReader in(found[6]);
    db.index_.resize(entries);
    for (std::uint64_t e = 0; e < entries; ++e) {
        PayloadInfo& p = db.index_[e];
        p.offset = in.u64();
        p.compressed_bytes = in.u32();
        p.raw_bytes = in.u32();
        p.checksum = in.u64();
        p.hit_pixels = in.u32();
        p.rays = in.u32();
        const std::string which = "index entry for view " + std::to_string(e / levels) + " level " +
                                  std::to_string(e % levels);
        const std::uint32_t side = db.params_.levels[e % levels];
        if (p.offset != at || p.compressed_bytes == 0 || p.compressed_bytes > size - at) {
            return fail(which + " points outside the file or out of order");
        }
        // A pixel holds at most 65535 rays (a 16-bit count), which also bounds what a damaged
        // index can make decode allocate.
        if (p.hit_pixels > static_cast<std::uint64_t>(side) * side || p.rays < p.hit_pixels ||
            p.rays > static_cast<std::uint64_t>(p.hit_pixels) * 65535u ||
            p.raw_bytes != payload_size(side, {p.hit_pixels, p.rays}, derivatives)) {
            return fail(which + " has impossible sizes or counts");
        }
        at += p.compressed_bytes;
    }
    if (at != size)
        return fail("payloads end at byte " + std::to_string(at) + ", not at the file's end");
    return db;
}

Result<DecodedView> Database::decode(std::uint32_t view, std::uint32_t level) const {
    const std::string where =
        path_.string() + ": view " + std::to_string(view) + " level " + std::to_string(level);
    if (view >= view_count() || level >= level_count()) return Error{where + " does not exist"};
    const PayloadInfo& info = payload(view, level);
    const std::uint8_t* compressed = map_->data + info.offset;
    if (XXH64(compressed, info.compressed_bytes, 0) != info.checksum) {
        return Error{where + ": checksum mismatch (payload damaged)"};
    }
    const unsigned long long content = ZSTD_getFrameContentSize(compressed, info.compressed_bytes);
    if (content != info.raw_bytes) return Error{where + ": compressed payload is damaged"};
    std::vector<std::uint8_t> raw(info.raw_bytes);
    const std::size_t n =
        ZSTD_decompress(raw.data(), raw.size(), compressed, info.compressed_bytes);
    if (ZSTD_isError(n) || n != raw.size()) return Error{where + ": compressed payload is damaged"};
    DecodedView out;
    auto counts = decode_payload(raw, params_.levels[level], params_.dispersion, box_, out);
    if (!counts) return Error{where + ": " + counts.error()};
    if (counts.value().hits != info.hit_pixels || counts.value().rays != info.rays) {
        return Error{where + ": payload counts disagree with the index"};
    }
    // Shading looks facets up by these numbers (light obstruction), so one past the stone's
    // facets is damage, not a number to trust.
    const std::size_t facets = stone_.facets.size();
    for (const std::uint16_t f : out.facet) {
        if (f >= facets)
            return Error{where + ": a ray names facet " + std::to_string(f) + " of a stone with " +
                         std::to_string(facets)};
    }
    return out;
}

}  // namespace gem
