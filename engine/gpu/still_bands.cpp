#include "gpu/still_bands.hpp"

#include <algorithm>
#include <cmath>

namespace gem::gpu {

void StillBands::start(int bands) {
    bands = std::max(bands, 1);
    // The last frame's costs, if it was whole in bands and measured.
    const bool measured =
        last_ms_.size() + 1 == last_edges_.size() && !last_ms_.empty() &&
        std::all_of(last_ms_.begin(), last_ms_.end(), [](double ms) { return ms > 0.0; });
    edges_.assign(static_cast<std::size_t>(bands) + 1, 0.0);
    edges_.back() = 1.0;
    double total = 0.0;
    if (measured) {
        for (const double ms : last_ms_) total += ms;
    }
    for (int k = 1; k < bands; ++k) {
        if (!measured) {
            edges_[static_cast<std::size_t>(k)] = static_cast<double>(k) / bands;
            continue;
        }
        // Where the cost, spread evenly over each of the last frame's bands, reaches k/bands of
        // the whole.
        double want = total * k / bands;
        std::size_t i = 0;
        while (i + 1 < last_ms_.size() && want > last_ms_[i]) want -= last_ms_[i++];
        const double share = std::clamp(want / last_ms_[i], 0.0, 1.0);
        edges_[static_cast<std::size_t>(k)] =
            last_edges_[i] + share * (last_edges_[i + 1] - last_edges_[i]);
    }
    ms_.assign(static_cast<std::size_t>(bands), 0.0);
}

void StillBands::measured(int band, double ms) {
    if (band < 0 || band >= bands()) return;
    ms_[static_cast<std::size_t>(band)] = ms;
    if (band + 1 == bands()) {
        last_edges_ = edges_;
        last_ms_ = ms_;
    }
}

double StillBands::dearest_ms() const {
    return ms_.empty() ? 0.0 : *std::max_element(ms_.begin(), ms_.end());
}

PixelRect StillBands::rows(const PixelRect& content, int band) const {
    const int h = content.height();
    const int n = bands();
    // Rounded edges, each at least a row past the last while rows remain (the edges, their
    // rounding and the bounds all rise with k, so the clamped edges do too).
    const auto edge = [&](int k) {
        if (k <= 0) return 0;
        if (k >= n) return h;
        const int at = static_cast<int>(std::lround(edges_[static_cast<std::size_t>(k)] * h));
        return std::clamp(at, std::min(k, h), std::max(h - (n - k), std::min(k, h)));
    };
    return PixelRect{content.x0, content.y0 + edge(band), content.x1, content.y0 + edge(band + 1)};
}

}  // namespace gem::gpu
