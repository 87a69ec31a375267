#pragma once
// Which tiles of a picture (32 pixels a side, unless told) a frame draws into, for passes that
// run only where the piece or its glare is: a ring seen at the kiosk's start view covers about
// half the tiles of the rectangle about it and its glare (bench_picture's section 5), and each
// pass after the scene costs llvmpipe as much for a background pixel as for the piece's. A
// pass draws a set's tiles as the few rectangles rects() merges them into, two triangles each
// in one draw (rect_draw.hpp): about 2 µs a rectangle on llvmpipe, where a scissored draw each
// costs about 20 (bench_pass_floor).

#include <cstdint>
#include <vector>

#include "gpu/pixel_rect.hpp"

namespace gem::gpu {

class TileSet {
  public:
    static constexpr int kTile = 32;  // pixels a side, unless told

    TileSet() = default;
    // No tile of a width × height picture, in tiles of `tile` pixels a side (the last row and
    // column may be partial tiles).
    TileSet(int width, int height, int tile = kTile);
    static TileSet whole(int width, int height);

    // Every tile `r` touches (clipped to the picture).
    void mark(const PixelRect& r);
    // Every tile of either (the same picture size).
    void add(const TileSet& other);
    // Every tile of a width × height picture unmarked (or marked), in the memory it had; the
    // tiles' size kept.
    void reset(int width, int height, bool marked = false);

    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const;
    long tile_count() const;
    // The pixels of the marked tiles, clipped to the picture.
    long area() const;
    bool has(int column, int row) const { return marked_[index(column, row)] != 0; }
    bool has_pixel(int x, int y) const { return has(x / tile_, y / tile_); }
    // The smallest rectangle of pixels holding every marked tile (empty: none).
    PixelRect bounds() const;
    // The marked tiles' pixels as disjoint rectangles, clipped to the picture: each tile row's
    // runs, a run joined with the one below where they span the same columns. Into `out`
    // (cleared first), so that a frame allocates nothing once it has run.
    void rects(std::vector<PixelRect>& out) const;
    bool operator==(const TileSet&) const = default;

  private:
    int columns() const { return (width_ + tile_ - 1) / tile_; }
    int rows() const { return (height_ + tile_ - 1) / tile_; }
    std::size_t index(int column, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns()) +
               static_cast<std::size_t>(column);
    }

    int tile_ = kTile;
    int width_ = 0;
    int height_ = 0;
    std::vector<std::uint8_t> marked_;  // row by row from the bottom (GL's rows count up)
};

// What a surface holds apart from the flat background it was cleared to, tile by tile, so that
// a frame rewrites only the tiles that change: those it draws into now and those it drew into
// last (which must go back to the background). A surface whose last content is unknown (never
// drawn, drawn over by something else, its background changed) is rewritten whole.
class TileDamage {
  public:
    // The tiles to rewrite for content `now` (null: the whole surface changes, as with a
    // background that is not one colour); remembers `now` as the surface's content.
    const TileSet& rewrite(const TileSet* now, int width, int height);
    // The surface was drawn outside this bookkeeping: the next frame rewrites it whole.
    void forget() { known_ = false; }

  private:
    TileSet last_;
    TileSet region_;
    bool known_ = false;
};

}  // namespace gem::gpu
