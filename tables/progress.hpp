#pragma once
// Build progress: a bar with the ETA redrawn in place when stdout is a terminal, a plain line
// every tenth otherwise (logs, CI). Safe to advance from several threads.

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>

namespace gem::tables {

class Progress {
  public:
    Progress(std::uint64_t total, bool terminal, std::FILE* out = stdout);
    void advance(std::uint64_t done = 1);
    void finish();  // ends the bar's line

    static bool stdout_is_terminal();

  private:
    void draw();

    std::mutex mutex_;
    std::uint64_t total_;
    std::uint64_t done_ = 0;
    bool terminal_;
    std::FILE* out_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::chrono::steady_clock::time_point last_draw_{};
    int last_tenth_ = 0;
};

}  // namespace gem::tables
