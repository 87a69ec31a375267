#pragma once
// The catalogue entry going on screen with its models (entry_models.hpp), and the next one's
// built ahead on a thread of its own: a tap shows the next entry, and reading a piece takes
// 17-80 ms (the shipped band, halo and trilogy), which the tap would otherwise wait for.

#include <future>
#include <optional>

#include "catalogue/catalogue.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

class NearEntries {
  public:
    NearEntries() = default;
    ~NearEntries();  // waits for a build in flight
    NearEntries(const NearEntries&) = delete;
    NearEntries& operator=(const NearEntries&) = delete;

    // `entry` with its models: the one built ahead where it is the same entry, else built now.
    // An error names the entry and its file's fault: the file no longer builds (changed or
    // gone since the catalogue was checked).
    Result<CatalogueStone> bring(const CatalogueStone& entry);
    // Builds `entry`'s models on a thread of its own, at SCHED_IDLE so that the frames go
    // first (nothing where it lacks none); a build in flight for another entry is waited for
    // and dropped.
    void build_ahead(const CatalogueStone& entry);

  private:
    void drop_ahead();

    // The entry being built ahead, as the catalogue names it (without its models).
    std::optional<CatalogueStone> ahead_entry_;
    std::future<Result<CatalogueStone>> ahead_;
};

}  // namespace gem::kiosk
