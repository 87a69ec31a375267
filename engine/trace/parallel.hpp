#pragma once
// Spreads a loop over every core: `fn(begin, end)` is called for consecutive chunks of
// [0, count) from std::thread::hardware_concurrency() threads, each taking the next chunk when
// it is done (dynamic scheduling, so uneven rows, e.g. the stone's silhouette, balance out).
// Returns when every chunk is done; fn must be safe to call concurrently on disjoint ranges.

#include <cstddef>
#include <functional>

namespace gem {

void parallel_for(std::size_t count, const std::function<void(std::size_t, std::size_t)>& fn,
                  std::size_t chunk = 1);

// Threads parallel_for uses (at least 1).
unsigned worker_count();

}  // namespace gem
