#pragma once
// What the benchmark programs share: how one stops on an error (one line naming the program and
// what failed, exit status 1: benchmarks print figures and have no error to recover from), and
// the median they quote.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "util/result.hpp"

namespace gem::bench {

[[noreturn]] inline void fail(const char* program, const std::string& why) {
    std::fprintf(stderr, "%s: %s\n", program, why.c_str());
    std::exit(1);
}

// The value of `r`, or the program stops with its error.
template <class T>
T must(const char* program, Result<T> r) {
    if (!r) fail(program, r.error());
    return std::move(r).value();
}

// The median of `v` (the upper one of an even count); 0 for none.
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace gem::bench
