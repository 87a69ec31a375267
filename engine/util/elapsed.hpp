#pragma once
// Wall time since a steady-clock instant, in milliseconds: what the passes, the method probe
// and the benchmarks time their work with.

#include <chrono>

namespace gem {

inline double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace gem
