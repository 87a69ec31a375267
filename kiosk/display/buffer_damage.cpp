#include "display/buffer_damage.hpp"

#include <algorithm>

namespace gem::kiosk {

const gpu::TileSet& BufferDamage::repaint(std::optional<int> age, const gpu::TileSet& changed) {
    // A picture of another size: no buffer holds any of it, and no change kept applies.
    const bool resized = known_ > 0 && (past_[0].width() != changed.width() ||
                                        past_[0].height() != changed.height());
    if (resized) known_ = 0;
    // Age 1: the buffer shows the last frame, and lacks this frame's change alone; age n lacks
    // the n − 1 frames' changes before it too.
    if (!resized && age && *age >= 1 && *age - 1 <= known_) {
        region_ = changed;
        for (int i = 0; i < *age - 1; ++i) region_.add(past_[i]);
    } else {
        region_.reset(changed.width(), changed.height(), true);
    }
    // The oldest kept's memory becomes the newest's.
    std::rotate(past_.begin(), past_.end() - 1, past_.end());
    past_[0] = changed;
    if (known_ < kFrames) ++known_;
    return region_;
}

}  // namespace gem::kiosk
