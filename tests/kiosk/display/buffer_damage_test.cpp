// The part of a back buffer a frame draws (display/buffer_damage.hpp), checked against three
// buffers drawn in turn as a GBM surface hands them out: each buffer, repainted where told,
// must end up holding exactly the picture of its frame.
#include <gtest/gtest.h>

#include <vector>

#include "display/buffer_damage.hpp"

namespace gem::kiosk {
namespace {

using gpu::PixelRect;

TEST(BufferDamage, ABufferOfAnyAgeIsRepaintedWhereItIsStale) {
    const int w = 12, h = 9;
    const PixelRect whole = PixelRect::whole(w, h);
    // The picture: each pixel holds the frame that last changed it.
    std::vector<int> picture(w * h, 0);
    // Three back buffers in turn, each remembering the frame it was last drawn at.
    constexpr int kBuffers = 3;
    std::vector<std::vector<int>> buffers(kBuffers, std::vector<int>(w * h, -1));
    std::vector<int> drawn_at(kBuffers, -1);
    const PixelRect changes[] = {{2, 2, 5, 5}, {6, 1, 9, 3},  {}, {0, 7, 3, 9}, {}, {},
                                 {4, 4, 6, 6}, {1, 1, 11, 8}, {}, {3, 0, 4, 9}};
    BufferDamage damage;
    int frame = 0, partial = 0;
    for (const PixelRect& change : changes) {
        ++frame;
        for (int y = change.y0; y < change.y1; ++y) {
            for (int x = change.x0; x < change.x1; ++x) picture[y * w + x] = frame;
        }
        const int b = frame % kBuffers;
        const std::optional<int> age =
            drawn_at[b] < 0 ? 0 : std::optional<int>(frame - drawn_at[b]);
        const PixelRect region = damage.repaint(age, change, whole);
        for (int y = region.y0; y < region.y1; ++y) {
            for (int x = region.x0; x < region.x1; ++x) buffers[b][y * w + x] = picture[y * w + x];
        }
        drawn_at[b] = frame;
        EXPECT_EQ(buffers[b], picture) << "frame " << frame << ", buffer age " << *age;
        if (region != whole) ++partial;
    }
    // Once every buffer has been drawn, each frame repaints only what changed since.
    EXPECT_EQ(partial, static_cast<int>(std::size(changes)) - kBuffers);
}

TEST(BufferDamage, AnUnknownOrTooOldBufferIsDrawnWhole) {
    const PixelRect whole = PixelRect::whole(100, 50);
    const PixelRect small{10, 10, 20, 20};
    BufferDamage damage;
    EXPECT_EQ(damage.repaint(std::nullopt, small, whole), whole);
    EXPECT_EQ(damage.repaint(1, small, whole), small);
    EXPECT_EQ(damage.repaint(0, small, whole), whole);  // undefined content
    EXPECT_EQ(damage.repaint(2, PixelRect{}, whole), small);
    // Older than the changes kept.
    EXPECT_EQ(damage.repaint(BufferDamage::kFrames + 2, small, whole), whole);
}

}  // namespace
}  // namespace gem::kiosk
