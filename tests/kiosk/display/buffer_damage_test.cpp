// The part of a back buffer a frame draws (display/buffer_damage.hpp), checked against three
// buffers drawn in turn as a GBM surface hands them out: each buffer, repainted where told,
// must end up holding exactly the picture of its frame.
#include <gtest/gtest.h>

#include <vector>

#include "display/buffer_damage.hpp"

namespace gem::kiosk {
namespace {

using gpu::PixelRect;
using gpu::TileSet;

TileSet tiles_of(const PixelRect& r, int w, int h) {
    TileSet t(w, h);
    t.mark(r);
    return t;
}

TEST(BufferDamage, ABufferOfAnyAgeIsRepaintedWhereItIsStale) {
    // Tiles of 32 pixels, 12 × 9 of them (the last column and row partial).
    const int w = 12 * 32 - 5, h = 9 * 32 - 7;
    // The picture, tile by tile: each holds the frame that last changed it.
    std::vector<int> picture(12 * 9, 0);
    // Three back buffers in turn, each remembering the frame it was last drawn at.
    constexpr int kBuffers = 3;
    std::vector<std::vector<int>> buffers(kBuffers, std::vector<int>(12 * 9, -1));
    std::vector<int> drawn_at(kBuffers, -1);
    // Changes in tiles: x0, y0, x1, y1.
    const PixelRect changes[] = {{2, 2, 5, 5}, {6, 1, 9, 3},  {}, {0, 7, 3, 9}, {}, {},
                                 {4, 4, 6, 6}, {1, 1, 11, 8}, {}, {3, 0, 4, 9}};
    BufferDamage damage;
    int frame = 0, partial = 0;
    for (const PixelRect& change : changes) {
        ++frame;
        for (int y = change.y0; y < change.y1; ++y) {
            for (int x = change.x0; x < change.x1; ++x) picture[y * 12 + x] = frame;
        }
        const PixelRect pixels{change.x0 * 32, change.y0 * 32, change.x1 * 32, change.y1 * 32};
        const int b = frame % kBuffers;
        const std::optional<int> age =
            drawn_at[b] < 0 ? 0 : std::optional<int>(frame - drawn_at[b]);
        const TileSet& region = damage.repaint(age, tiles_of(pixels, w, h));
        for (int y = 0; y < 9; ++y) {
            for (int x = 0; x < 12; ++x) {
                if (region.has(x, y)) buffers[b][y * 12 + x] = picture[y * 12 + x];
            }
        }
        drawn_at[b] = frame;
        EXPECT_EQ(buffers[b], picture) << "frame " << frame << ", buffer age " << *age;
        if (region != TileSet::whole(w, h)) ++partial;
    }
    // Once every buffer has been drawn, each frame repaints only what changed since.
    EXPECT_EQ(partial, static_cast<int>(std::size(changes)) - kBuffers);
}

TEST(BufferDamage, AnUnknownOrTooOldBufferIsDrawnWhole) {
    const int w = 100, h = 50;
    const TileSet whole = TileSet::whole(w, h);
    const TileSet small = tiles_of({10, 10, 20, 20}, w, h);
    const TileSet none(w, h);
    BufferDamage damage;
    EXPECT_EQ(damage.repaint(std::nullopt, small), whole);
    EXPECT_EQ(damage.repaint(1, small), small);
    EXPECT_EQ(damage.repaint(0, small), whole);  // undefined content
    EXPECT_EQ(damage.repaint(2, none), small);
    // Older than the changes kept.
    EXPECT_EQ(damage.repaint(BufferDamage::kFrames + 2, small), whole);
    // A picture of another size: nothing kept applies.
    EXPECT_EQ(damage.repaint(1, TileSet(w + 40, h)), TileSet::whole(w + 40, h));
}

}  // namespace
}  // namespace gem::kiosk
