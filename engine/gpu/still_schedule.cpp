#include "gpu/still_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace gem::gpu {

int StillSchedule::wanted_depth(int index) const {
    if (options_.depth <= 0) return 0;
    const int deepest = std::max(options_.depth, options_.depth_max);
    int depth = options_.depth;
    for (int frames = kFramesAtFirstDepth; index >= frames && depth < deepest; frames *= 2) {
        depth *= 2;
    }
    return std::min(depth, deepest);
}

void StillSchedule::begin_frame(bool still, double now_s) {
    if (!still || options_.frames <= 1) {
        index_ = -1;
        depth_ = 0;
        bands_ = 1;
        settled_ = false;
        ms_per_depth_ = 0.0;
        deepest_ = 0;
        return;
    }
    if (settled_) return;
    if (index_ < 0) started_s_ = now_s;
    const bool out_of_time = options_.seconds > 0.0 && now_s - started_s_ >= options_.seconds;
    if (index_ + 1 >= options_.frames || (index_ >= 0 && out_of_time)) {
        settled_ = true;
        settled_s_ = now_s;
        depth_ = 0;
        bands_ = 1;
        return;
    }
    ++index_;
    depth_ = wanted_depth(index_);
    bands_ = 1;
    // The view's first frame is the moving view's own, whole. Without a bound every frame is
    // whole and as deep as the rule says; with one, none is deeper than the first depth until a
    // frame has been measured.
    if (index_ == 0 || options_.frame_ms <= 0.0) return note_depth();
    if (ms_per_depth_ <= 0.0) {
        depth_ = std::min(depth_, options_.depth);
        return note_depth();
    }
    // Back down the doubling while even kMostBands bands would keep a touch waiting too long.
    const auto bands_for = [&](int depth) {
        return static_cast<int>(std::ceil(ms_per_depth_ * depth / options_.frame_ms));
    };
    while (depth_ > options_.depth && bands_for(depth_) > kMostBands) {
        depth_ = std::max(depth_ / 2, options_.depth);
    }
    bands_ = std::clamp(bands_for(depth_), 1, kMostBands);
    note_depth();
}

void StillSchedule::note_depth() {
    deepest_ = std::max(deepest_, depth_);
}

void StillSchedule::frame_drawn(double ms) {
    // The view's first frame is multisampled (HdrPicture::multisampled_frame): not what the
    // point-sampled frames after it cost. A frame in bands paid what is not traced once a band,
    // so its cost per depth overstates the trace's: the next frame's bands err on the many.
    if (index_ >= 1 && depth_ > 0 && ms > 0.0) ms_per_depth_ = ms / depth_;
}

}  // namespace gem::gpu
