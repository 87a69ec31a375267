#pragma once
// Where a still frame drawn in bands (StillSchedule::bands()) splits the picture's rows. The
// work is not spread evenly over the rows: a stone's rows cost many times its shank's, so rows
// split evenly leave one band dear and the others cheap, and the dearest is what a touch waits
// for (on llvmpipe at 1920×1080 the halo's bands, rows split evenly, took 20 to 250 ms). So each
// frame's bands are placed by the last frame's: each band's cost taken as spread evenly over
// its rows, the new edges at equal shares of the whole.

#include <vector>

#include "gpu/pixel_rect.hpp"

namespace gem::gpu {

class StillBands {
  public:
    // A new frame in `bands` bands, placed by the last frame's costs (evenly at first).
    void start(int bands);
    // Band `band` of this frame took `ms`.
    void measured(int band, double ms);
    // The dearest band of this frame so far (ms).
    double dearest_ms() const;
    int bands() const { return static_cast<int>(edges_.size()) - 1; }
    // Band `band`'s rows of `content` (every row in exactly one band; none empty where the
    // content has as many rows as bands).
    PixelRect rows(const PixelRect& content, int band) const;

  private:
    std::vector<double> edges_{0.0, 1.0};  // shares of the content's rows, from its first
    std::vector<double> ms_;               // this frame's bands' costs
    // The last whole frame's edges and costs, what the next is placed by.
    std::vector<double> last_edges_;
    std::vector<double> last_ms_;
};

}  // namespace gem::gpu
