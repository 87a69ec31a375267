#pragma once
// Which part of a window surface's back buffer a frame must draw. A GBM surface hands back
// one of two or three buffers in turn, each holding the picture as it was when that buffer
// was last drawn; EGL_EXT_buffer_age says how many frames ago that was. The buffer then lacks
// this frame's change and the changes of the frames since (as compositors repaint: the
// extension's own example), and nothing else.

#include <array>
#include <optional>

#include "gpu/tile_set.hpp"

namespace gem::kiosk {

class BufferDamage {
  public:
    // Frames of changes kept: a buffer older than this is drawn whole.
    static constexpr int kFrames = 4;

    // The tiles of a back buffer drawn `age` frames ago (0: its content is undefined; nullopt:
    // EGL cannot tell) to draw for a frame whose picture changed in `changed`: `changed` and
    // every change since that buffer was drawn; all of them where that is unknown. Remembers
    // `changed` for the frames after.
    const gpu::TileSet& repaint(std::optional<int> age, const gpu::TileSet& changed);

  private:
    std::array<gpu::TileSet, kFrames> past_{};  // past_[0]: the last frame's change
    int known_ = 0;                             // frames recorded in past_
    gpu::TileSet region_;
};

}  // namespace gem::kiosk
