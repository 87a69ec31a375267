#pragma once
// Reads a .gemdb database (docs/gemdb-format.md) through a read-only memory map. open()
// checks the header, every section and the index against the file size, limits and
// checksums before trusting anything; decode() verifies a view's checksum before it
// decompresses it. Every fault is an Error naming the file and what is wrong.

#include <cstdint>
#include <filesystem>
#include <memory>

#include "gemdb/database_types.hpp"
#include "gemdb/quantise.hpp"
#include "gemdb/view_grid.hpp"
#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem {

struct PayloadInfo {
    std::uint64_t offset = 0;
    std::uint32_t compressed_bytes = 0;
    std::uint32_t raw_bytes = 0;
    std::uint64_t checksum = 0;  // xxHash64 (seed 0) of the compressed bytes
    std::uint32_t hit_pixels = 0;
    std::uint32_t rays = 0;
};

class Database {
  public:
    static Result<Database> open(const std::filesystem::path& path);

    const std::filesystem::path& path() const { return path_; }
    std::uint16_t version_minor() const { return version_minor_; }
    const Stone& stone() const { return stone_; }  // with its material
    const Material& material() const { return stone_.material; }
    const CameraModel& camera() const { return camera_; }
    const BuildParams& params() const { return params_; }
    const PositionBox& position_box() const { return box_; }
    const ViewGrid& grid() const { return grid_; }
    std::uint32_t view_count() const { return static_cast<std::uint32_t>(grid_.size()); }
    std::uint32_t level_count() const { return static_cast<std::uint32_t>(params_.levels.size()); }
    const PayloadInfo& payload(std::uint32_t view, std::uint32_t level) const {
        return index_[static_cast<std::size_t>(view) * level_count() + level];
    }

    // Thread-safe: several decode threads may share one Database.
    Result<DecodedView> decode(std::uint32_t view, std::uint32_t level) const;

  private:
    struct Mapping;
    Database() = default;
    std::filesystem::path path_;
    std::shared_ptr<const Mapping> map_;
    std::uint16_t version_minor_ = 0;
    Stone stone_;
    CameraModel camera_;
    BuildParams params_;
    PositionBox box_;
    ViewGrid grid_;
    std::vector<PayloadInfo> index_;
};

}  // namespace gem
