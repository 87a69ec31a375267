#include "gemdb/writer.hpp"

#include <xxhash.h>
#include <zstd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <thread>

#include "gemdb/bytes.hpp"
#include "gemdb/format.hpp"
#include "gemdb/payload.hpp"
#include "gemdb/sections.hpp"
#include "util/atomic_file.hpp"

namespace gem {

namespace {

struct Chunk {
    std::vector<std::uint8_t> compressed;
    std::uint64_t raw_size = 0;
    PayloadCounts counts;
    std::optional<std::string> error;
};

std::optional<std::string> check_inputs(const Stone& stone, const CameraModel& camera,
                                        const BuildParams& params, const ViewGrid& grid,
                                        bool have_derivatives) {
    if (params.levels.empty() || params.levels.size() > gemdb::kMaxLevels) {
        return "params.levels must hold 1 .. 16 sides";
    }
    for (std::size_t l = 0; l < params.levels.size(); ++l) {
        const std::uint32_t side = params.levels[l];
        if (side == 0 || side > gemdb::kMaxSide || (l > 0 && side <= params.levels[l - 1])) {
            return "params.levels[" + std::to_string(l) + "] = " + std::to_string(side) +
                   ": sides must ascend and lie in 1 .. 8192";
        }
    }
    if (!(params.weight_threshold >= 0.0 && params.weight_threshold <= 1.0)) {
        return "params.weight_threshold must lie in 0 .. 1";
    }
    if (params.dispersion && !have_derivatives) {
        return "params.dispersion is on but no derivative callback was given";
    }
    if (!(camera.field_mm > 0.0 && std::isfinite(camera.field_mm)) ||
        (camera.kind == CameraModel::Kind::perspective &&
         !(camera.distance_mm > 0.0 && std::isfinite(camera.distance_mm)))) {
        return "camera.field_mm (and for perspective distance_mm) must be positive";
    }
    if (grid.spec().spacing_rad != params.grid.spacing_rad ||
        grid.spec().min_elevation_rad != params.grid.min_elevation_rad) {
        return "the view grid was not built from params.grid";
    }
    for (std::size_t i = 0; i < grid.group_indices().size(); ++i) {
        const std::uint32_t s = grid.group_indices()[i];
        if (s >= stone.symmetry.size() || stone.symmetry[s] != grid.group()[i]) {
            return "the view grid was not built from the stone's symmetry";
        }
    }
    if (grid.size() > gemdb::kMaxViews) return "the view grid has too many views";
    if (stone.vertices.empty() || stone.vertices.size() > gemdb::kMaxVertices ||
        stone.facets.size() > gemdb::kMaxFacets || stone.triangles.size() > gemdb::kMaxTriangles ||
        stone.symmetry.size() > gemdb::kMaxSymmetry ||
        stone.material.dispersion.coef.size() > gemdb::kMaxCoefficients) {
        return "the stone is empty or exceeds the format's limits";
    }
    // Each kind needs its coefficients: constant one, Cauchy two, Sellmeier (B, C) pairs. The
    // reader refuses any other count, so a file written with one could never be opened.
    const Dispersion& dispersion = stone.material.dispersion;
    const std::size_t coefficients = dispersion.coef.size();
    const bool fits = dispersion.kind == Dispersion::Kind::constant ? coefficients >= 1
                      : dispersion.kind == Dispersion::Kind::cauchy
                          ? coefficients >= 2
                          : coefficients >= 2 && coefficients % 2 == 0;
    if (!fits) {
        return "stone.material.dispersion has " + std::to_string(coefficients) +
               " coefficients, which do not fit its kind (constant needs 1 or more, Cauchy 2 "
               "or more, Sellmeier an even count of 2 or more)";
    }
    return std::nullopt;
}

// The reader refuses a ray naming a facet the stone does not have, so the writer does too.
std::optional<std::string> check_facets(const std::vector<RayList>& lists, std::size_t facets) {
    auto bad = [&](const TracedRay& ray) { return ray.facet >= facets; };
    for (const RayList& list : lists) {
        if (!list.hit) continue;
        const TracedRay* wrong = bad(list.reflected) ? &list.reflected : nullptr;
        for (std::size_t e = 0; wrong == nullptr && e < list.exits.size(); ++e) {
            if (bad(list.exits[e])) wrong = &list.exits[e];
        }
        if (wrong != nullptr) {
            return "a ray names facet " + std::to_string(wrong->facet) + " of a stone with " +
                   std::to_string(facets);
        }
    }
    return std::nullopt;
}

Chunk make_chunk(std::uint32_t view, std::uint32_t level, std::size_t facets,
                 const BuildParams& params, const PositionBox& box, const TraceViewFn& trace_view,
                 const TraceDerivativesFn& trace_derivatives, int zstd_level) {
    Chunk chunk;
    const std::string where = "view " + std::to_string(view) + " level " + std::to_string(level);
    try {
        const std::vector<RayList> lists = trace_view(view, level);
        if (auto bad = check_facets(lists, facets)) {
            chunk.error = where + ": " + *bad;
            return chunk;
        }
        std::optional<std::vector<glm::dvec3>> derivatives;
        if (params.dispersion) derivatives = trace_derivatives(view, level, lists);
        std::vector<std::uint8_t> raw;
        auto counts = encode_payload(lists, derivatives ? &*derivatives : nullptr,
                                     params.levels[level], box, params.weight_threshold, raw);
        if (!counts) {
            chunk.error = where + ": " + counts.error();
            return chunk;
        }
        if (raw.size() >= gemdb::kMaxRawPayload) {
            chunk.error = where + ": payload exceeds 4 GiB";
            return chunk;
        }
        chunk.counts = counts.value();
        chunk.raw_size = raw.size();
        chunk.compressed.resize(ZSTD_compressBound(raw.size()));
        const std::size_t n = ZSTD_compress(chunk.compressed.data(), chunk.compressed.size(),
                                            raw.data(), raw.size(), zstd_level);
        if (ZSTD_isError(n)) {
            chunk.error = where + ": zstd: " + ZSTD_getErrorName(n);
            return chunk;
        }
        chunk.compressed.resize(n);
    } catch (const std::exception& e) {
        chunk.error = where + ": tracing failed: " + e.what();
    }
    return chunk;
}

}  // namespace

Result<WriteSummary> write_database(const std::filesystem::path& path, const Stone& stone,
                                    const CameraModel& camera, const BuildParams& params,
                                    const ViewGrid& grid, const TraceViewFn& trace_view,
                                    const TraceDerivativesFn& trace_derivatives,
                                    const WriteOptions& options) {
    auto error = [&](const std::string& what) {
        return Error{"cannot write " + path.string() + ": " + what};
    };
    if (auto bad = check_inputs(stone, camera, params, grid, bool(trace_derivatives)))
        return error(*bad);

    PositionBox box{stone.vertices[0], stone.vertices[0]};
    for (const glm::dvec3& v : stone.vertices) {
        box.min = glm::min(box.min, v);
        box.max = glm::max(box.max, v);
    }
    if (!(box.max.x > box.min.x && box.max.y > box.min.y && box.max.z > box.min.z)) {
        return error("the stone is flat (its bounding box has no volume)");
    }

    std::array<ByteWriter, 5> meta;
    write_stone_section(meta[0], stone);
    write_material_section(meta[1], stone.material);
    write_camera_section(meta[2], camera);
    write_params_section(meta[3], params, box);
    write_grid_section(meta[4], grid);

    const auto views = static_cast<std::uint32_t>(grid.size());
    const auto levels = static_cast<std::uint32_t>(params.levels.size());
    const std::uint32_t header_bytes =
        gemdb::kHeaderFixedBytes + gemdb::kRequiredSections * gemdb::kSectionRecordBytes + 8;
    std::array<std::uint64_t, gemdb::kRequiredSections> offset{};
    std::array<std::uint64_t, gemdb::kRequiredSections> size{};
    std::array<std::uint64_t, gemdb::kRequiredSections> hash{};
    std::uint64_t at = header_bytes;
    for (std::size_t s = 0; s < meta.size(); ++s) {
        offset[s] = at;
        size[s] = meta[s].size();
        hash[s] = XXH64(meta[s].bytes().data(), meta[s].size(), 0);
        at += size[s];
    }
    offset[5] = at;
    size[5] = static_cast<std::uint64_t>(views) * levels * gemdb::kIndexRecordBytes;

    auto file = AtomicFile::create(path);
    if (!file) return Error{file.error()};
    AtomicFile& out = file.value();
    const std::vector<std::uint8_t> zeros(std::max<std::uint64_t>(header_bytes, size[5]), 0);
    if (auto ok = out.append(zeros.data(), header_bytes); !ok) return Error{ok.error()};
    for (ByteWriter& m : meta) {
        if (auto ok = out.append(m.bytes().data(), m.size()); !ok) return Error{ok.error()};
    }
    if (auto ok = out.append(zeros.data(), size[5]); !ok) return Error{ok.error()};

    // Views are produced in batches, in parallel, then written in index order, so the bytes
    // never depend on which thread finished first.
    WriteSummary summary;
    ByteWriter index;
    const std::uint64_t total = static_cast<std::uint64_t>(views) * levels;
    const unsigned threads = std::max(1u, options.threads);
    const std::uint64_t batch = 2ull * threads;
    for (std::uint64_t start = 0; start < total; start += batch) {
        const std::uint64_t count = std::min(batch, total - start);
        std::vector<Chunk> chunks(count);
        std::atomic<std::uint64_t> next{0};
        auto work = [&] {
            for (std::uint64_t i = next++; i < count; i = next++) {
                const std::uint64_t k = start + i;
                chunks[i] =
                    make_chunk(static_cast<std::uint32_t>(k / levels),
                               static_cast<std::uint32_t>(k % levels), stone.facets.size(), params,
                               box, trace_view, trace_derivatives, options.zstd_level);
            }
        };
        if (threads == 1) {
            work();
        } else {
            std::vector<std::thread> pool;
            for (unsigned t = 0; t < std::min<std::uint64_t>(threads, count); ++t)
                pool.emplace_back(work);
            for (std::thread& t : pool) t.join();
        }
        for (const Chunk& chunk : chunks) {
            if (chunk.error) return error(*chunk.error);
            index.u64(out.size());
            index.u32(static_cast<std::uint32_t>(chunk.compressed.size()));
            index.u32(static_cast<std::uint32_t>(chunk.raw_size));
            index.u64(XXH64(chunk.compressed.data(), chunk.compressed.size(), 0));
            index.u32(chunk.counts.hits);
            index.u32(chunk.counts.rays);
            if (auto ok = out.append(chunk.compressed.data(), chunk.compressed.size()); !ok) {
                return Error{ok.error()};
            }
            summary.raw_payload_bytes += chunk.raw_size;
            summary.rays += chunk.counts.rays;
            summary.hit_pixels += chunk.counts.hits;
        }
    }
    assert(index.size() == size[5]);
    hash[5] = XXH64(index.bytes().data(), index.size(), 0);

    ByteWriter header;
    header.raw(gemdb::kMagic);
    header.u16(gemdb::kVersionMajor);
    header.u16(gemdb::kVersionMinor);
    header.u32(params.dispersion ? gemdb::kFlagDerivatives : 0u);
    header.u32(header_bytes);
    header.u32(gemdb::kRequiredSections);
    header.u64(out.size());
    header.u32(views);
    header.u32(levels);
    header.u64(0);
    for (std::uint32_t s = 0; s < gemdb::kRequiredSections; ++s) {
        header.u32(s + 1);
        header.u32(0);
        header.u64(offset[s]);
        header.u64(size[s]);
        header.u64(hash[s]);
    }
    header.u64(XXH64(header.bytes().data(), header.size(), 0));
    assert(header.size() == header_bytes);
    if (auto ok = out.write_at(0, header.bytes().data(), header.size()); !ok)
        return Error{ok.error()};
    if (auto ok = out.write_at(offset[5], index.bytes().data(), index.size()); !ok)
        return Error{ok.error()};
    summary.file_bytes = out.size();
    if (auto ok = out.commit(); !ok) return Error{ok.error()};
    return summary;
}

}  // namespace gem
