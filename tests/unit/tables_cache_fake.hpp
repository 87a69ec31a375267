#pragma once
// A stand-in view source for the view cache tests: a plain view grid, views of a known size
// whose contents name the view, an optional delay per decode (a slow disk) and damaged views.

#include <chrono>
#include <cstdint>
#include <mutex>
#include <numbers>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "tables/view_cache.hpp"

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

    const ViewGrid& grid() const override { return grid_; }
    std::uint32_t level_count() const override { return levels_; }
    Result<DecodedView> decode(std::uint32_t view, std::uint32_t level) const override {
        std::this_thread::sleep_for(delay);
        {
            std::lock_guard lock(mutex_);
            decoded_.emplace_back(view, level);
        }
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
    mutable std::vector<std::pair<std::uint32_t, std::uint32_t>> decoded_;
};

}  // namespace gem::cache_test
