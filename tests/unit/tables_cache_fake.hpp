#pragma once
// A stand-in view source for the view cache tests: a plain view grid, views of a known size
// whose contents name the view, an optional delay per decode (a slow disk), a gate that holds
// every decode until the test opens it (a disk that has not answered yet) and damaged views.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <numbers>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "gemdb/view_cache.hpp"

namespace gem::cache_test {

class FakeSource final : public ViewSource {
  public:
    // `floats_per_view` floats per view at every level, so a view holds 4 × that many bytes.
    FakeSource(double spacing_rad, std::uint32_t levels, std::size_t floats_per_view)
        : grid_(ViewGrid::build({spacing_rad, -std::numbers::pi / 2.0}, {glm::dmat3(1.0)}).value()),
          levels_(levels),
          floats_(floats_per_view) {}

    std::chrono::milliseconds delay{0};
    std::set<std::pair<std::uint32_t, std::uint32_t>> damaged;
    // What decoded_bytes_at_least() claims for every view (an index that promises too much).
    std::uint64_t claimed_bytes = 0;

    // While the gate is shut, decode() waits (at most a minute, so a broken cache that waits
    // on its own decode fails its test instead of hanging the suite).
    void shut_gate() {
        std::lock_guard lock(mutex_);
        gate_open_ = false;
    }
    void open_gate() {
        {
            std::lock_guard lock(mutex_);
            gate_open_ = true;
        }
        gate_.notify_all();
    }
    // Decodes that have returned so far.
    int finished() const { return finished_.load(); }

    const ViewGrid& grid() const override { return grid_; }
    std::uint32_t level_count() const override { return levels_; }
    std::uint64_t decoded_bytes_at_least(std::uint32_t, std::uint32_t) const override {
        return claimed_bytes;
    }
    Result<DecodedView> decode(std::uint32_t view, std::uint32_t level) const override {
        {
            std::unique_lock lock(mutex_);
            gate_.wait_for(lock, std::chrono::minutes(1), [this] { return gate_open_; });
        }
        std::this_thread::sleep_for(delay);
        {
            std::lock_guard lock(mutex_);
            decoded_.emplace_back(view, level);
        }
        struct Finished {
            std::atomic<int>& count;
            ~Finished() { ++count; }
        } finished{finished_};
        if (damaged.contains({view, level})) return Error{"fake: view damaged"};
        DecodedView v;
        v.side = level + 1;
        v.weight = std::vector<float>(floats_, static_cast<float>(view));
        return v;
    }

    // Every (view, level) decode() was called with, in order.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> decoded() const {
        std::lock_guard lock(mutex_);
        return decoded_;
    }

  private:
    ViewGrid grid_;
    std::uint32_t levels_;
    std::size_t floats_;
    mutable std::mutex mutex_;
    mutable std::condition_variable gate_;
    bool gate_open_ = true;
    mutable std::atomic<int> finished_{0};
    mutable std::vector<std::pair<std::uint32_t, std::uint32_t>> decoded_;
};

}  // namespace gem::cache_test
