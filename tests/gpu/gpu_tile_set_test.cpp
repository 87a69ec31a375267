// The tiles a frame draws into (gpu/tile_set.hpp): rects() against the marked tiles counted
// pixel by pixel (every marked pixel in exactly one rectangle, no other pixel in any), and
// TileDamage's rule (this frame's tiles and the last's; all of them when unknown).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "gpu/tile_set.hpp"

namespace gem::gpu {
namespace {

// How many of `rects` hold each pixel of a width × height picture.
std::vector<int> coverage(const std::vector<PixelRect>& rects, int width, int height) {
    std::vector<int> count(static_cast<std::size_t>(width) * height, 0);
    for (const PixelRect& r : rects) {
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) ++count[static_cast<std::size_t>(y) * width + x];
        }
    }
    return count;
}

TEST(GpuTileSet, ItsRectanglesHoldEveryMarkedPixelOnceAndNoOther) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 40; ++trial) {
        // Sizes that leave partial tiles, and some of exact tiles.
        const int w = 64 + static_cast<int>(random() % 200),
                  h = 40 + static_cast<int>(random() % 150);
        const int tile = trial % 3 == 0 ? TileSet::kTile : 8 + static_cast<int>(random() % 20);
        TileSet set(w, h, tile);
        std::vector<PixelRect> marked;
        const int marks = static_cast<int>(random() % 6);
        for (int m = 0; m < marks; ++m) {
            const int x = static_cast<int>(random() % (w + 20)) - 10;
            const int y = static_cast<int>(random() % (h + 20)) - 10;
            const PixelRect r{x, y, x + 1 + static_cast<int>(random() % 90),
                              y + 1 + static_cast<int>(random() % 60)};
            set.mark(r);
            marked.push_back(r);
        }
        std::vector<PixelRect> rects;
        set.rects(rects);
        const std::vector<int> count = coverage(rects, w, h);
        // A pixel's tile is marked where a marked rectangle's pixels on the picture touch that
        // tile: worked out here from the tiles' own bounds, not through the set.
        long pixels = 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const PixelRect its_tile{x / tile * tile, y / tile * tile, x / tile * tile + tile,
                                         y / tile * tile + tile};
                bool in_marked_tile = false;
                for (const PixelRect& r : marked) {
                    in_marked_tile =
                        in_marked_tile || !intersected(clamped(r, w, h), its_tile).empty();
                }
                const int n = count[static_cast<std::size_t>(y) * w + x];
                ASSERT_EQ(n, in_marked_tile ? 1 : 0)
                    << "pixel " << x << ", " << y << " of " << w << "×" << h << ", trial " << trial;
                pixels += n;
            }
        }
        EXPECT_EQ(pixels, set.area());
        EXPECT_EQ(set.empty(), pixels == 0);
        PixelRect about;
        for (const PixelRect& r : rects) about = united(about, r);
        EXPECT_EQ(set.bounds(), about);
    }
}

TEST(GpuTileSet, TilesInABlockAreOneRectangle) {
    TileSet set(200, 100);
    set.mark({40, 10, 130, 70});  // tiles 1..4 across, 0..2 up
    std::vector<PixelRect> rects;
    set.rects(rects);
    ASSERT_EQ(rects.size(), 1u);
    EXPECT_EQ(rects[0], (PixelRect{32, 0, 160, 96}));
    EXPECT_EQ(set.tile_count(), 12);
    // The last column is 8 pixels wide, the last row 4 high.
    EXPECT_EQ(TileSet::whole(200, 100).area(), 200 * 100);
}

TEST(GpuTileSet, ASurfaceRewritesItsLastTilesAndItsNewOnesAndAllWhenUnknown) {
    const int w = 100, h = 80;
    const TileSet whole = TileSet::whole(w, h);
    TileSet first(w, h), second(w, h), both(w, h);
    first.mark({10, 10, 20, 20});
    second.mark({50, 40, 60, 45});
    both.mark({10, 10, 20, 20});
    both.mark({50, 40, 60, 45});
    TileDamage damage;
    EXPECT_EQ(damage.rewrite(&first, w, h), whole);  // never drawn: all of it
    EXPECT_EQ(damage.rewrite(&second, w, h), both);
    EXPECT_EQ(damage.rewrite(&second, w, h), second);
    EXPECT_EQ(damage.rewrite(nullptr, w, h), whole);  // the background is not flat
    EXPECT_EQ(damage.rewrite(&first, w, h), whole);   // ... so the next frame too
    damage.forget();
    EXPECT_EQ(damage.rewrite(&first, w, h), whole);
    EXPECT_EQ(damage.rewrite(&first, w, h), first);
    // Another picture size: all of the new one.
    const TileSet other(w + 50, h);
    EXPECT_EQ(damage.rewrite(&other, w + 50, h), TileSet::whole(w + 50, h));
}

}  // namespace
}  // namespace gem::gpu
