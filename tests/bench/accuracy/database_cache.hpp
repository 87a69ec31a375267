#pragma once
// Ray-table databases for the sweep, built once (as `gemtables build` builds them, through
// tables::trace_and_write) and kept in a cache folder with their build time beside them, so a
// second run of the benchmark only renders.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "gemdb/reader.hpp"
#include "geometry/stone.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

// One point of the table settings (the base point of the sweep by default).
struct TableConfig {
    std::uint32_t level = 256;  // table side, pixels (one level per database)
    double spacing_deg = 6.0;   // angular spacing of the stored directions
    int depth = 8;              // tracer depth
    double threshold = 1e-4;    // exit rays lighter than this are dropped
    bool dispersion = false;    // d(direction)/dn stored per exit ray
};

struct CachedDatabase {
    std::shared_ptr<const Database> database;
    std::uint64_t bytes = 0;  // file size
    double build_s = 0.0;     // wall time of the build (on this machine, when it was built)
    bool from_cache = false;
};

class DatabaseCache {
  public:
    explicit DatabaseCache(std::filesystem::path folder) : folder_(std::move(folder)) {}
    // The database of `stone` (family name `stone_name`) for `config`, views above
    // `min_elevation_deg`; built and timed unless the folder already holds it.
    Result<CachedDatabase> get(const std::string& stone_name, const Stone& stone,
                               const TableConfig& config, double min_elevation_deg);

  private:
    std::filesystem::path folder_;
};

std::string describe(const TableConfig& config);

}  // namespace gem::accuracy
