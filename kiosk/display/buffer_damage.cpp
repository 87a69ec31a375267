#include "display/buffer_damage.hpp"

namespace gem::kiosk {

gpu::PixelRect BufferDamage::repaint(std::optional<int> age, const gpu::PixelRect& changed,
                                     const gpu::PixelRect& whole) {
    // Age 1: the buffer shows the last frame, and lacks this frame's change alone; age n lacks
    // the n − 1 frames' changes before it too.
    gpu::PixelRect region = whole;
    if (age && *age >= 1 && *age - 1 <= known_) {
        region = changed;
        for (int i = 0; i < *age - 1; ++i) region = gpu::united(region, past_[i]);
    }
    for (int i = kFrames - 1; i > 0; --i) past_[i] = past_[i - 1];
    past_[0] = changed;
    if (known_ < kFrames) ++known_;
    return region;
}

}  // namespace gem::kiosk
