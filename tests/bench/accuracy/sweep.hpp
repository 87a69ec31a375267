#pragma once
// The sweep itself: for every scene, the views ON and BETWEEN stored directions, every method
// and the table settings varied one at a time around the base point, each measured against
// the reference; and a path of views across the gap between two stored directions.

#include <filesystem>
#include <vector>

#include "results.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

struct SweepOptions {
    bool quick = false;
    int image = 256;  // square frame side; the base table level equals it
    int frames = 5;   // timed frames per point (median)
    std::filesystem::path cache;
    std::filesystem::path images;  // example pictures go here ("" = none)
};

// Needs a current GL context. Prints each row as it is measured.
Result<std::vector<Row>> run_sweep(const SweepOptions& options);

}  // namespace gem::accuracy
