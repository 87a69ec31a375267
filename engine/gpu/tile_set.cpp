#include "gpu/tile_set.hpp"

#include <algorithm>

namespace gem::gpu {

TileSet::TileSet(int width, int height, int tile) : tile_(std::max(tile, 1)) {
    reset(width, height);
}

TileSet TileSet::whole(int width, int height) {
    TileSet t;
    t.reset(width, height, true);
    return t;
}

void TileSet::reset(int width, int height, bool marked) {
    width_ = std::max(width, 0);
    height_ = std::max(height, 0);
    marked_.assign(static_cast<std::size_t>(columns()) * static_cast<std::size_t>(rows()),
                   marked ? std::uint8_t{1} : std::uint8_t{0});
}

void TileSet::mark(const PixelRect& r) {
    const PixelRect c = clamped(r, width_, height_);
    if (c.empty()) return;
    for (int row = c.y0 / tile_; row <= (c.y1 - 1) / tile_; ++row) {
        std::fill_n(marked_.begin() + static_cast<std::ptrdiff_t>(index(c.x0 / tile_, row)),
                    (c.x1 - 1) / tile_ - c.x0 / tile_ + 1, std::uint8_t{1});
    }
}

void TileSet::add(const TileSet& other) {
    for (std::size_t i = 0; i < marked_.size() && i < other.marked_.size(); ++i) {
        marked_[i] |= other.marked_[i];
    }
}

bool TileSet::empty() const {
    return std::none_of(marked_.begin(), marked_.end(), [](std::uint8_t m) { return m != 0; });
}

long TileSet::tile_count() const {
    return static_cast<long>(std::count(marked_.begin(), marked_.end(), std::uint8_t{1}));
}

long TileSet::area() const {
    long pixels = 0;
    for (int row = 0; row < rows(); ++row) {
        for (int column = 0; column < columns(); ++column) {
            if (!has(column, row)) continue;
            pixels += static_cast<long>(std::min(tile_, width_ - column * tile_)) *
                      std::min(tile_, height_ - row * tile_);
        }
    }
    return pixels;
}

PixelRect TileSet::bounds() const {
    PixelRect b;
    for (int row = 0; row < rows(); ++row) {
        for (int column = 0; column < columns(); ++column) {
            if (has(column, row)) {
                b = united(b,
                           {column * tile_, row * tile_, (column + 1) * tile_, (row + 1) * tile_});
            }
        }
    }
    return clamped(b, width_, height_);
}

void TileSet::rects(std::vector<PixelRect>& out) const {
    out.clear();
    for (int row = 0; row < rows(); ++row) {
        for (int column = 0; column < columns();) {
            if (!has(column, row)) {
                ++column;
                continue;
            }
            const int first = column;
            while (column < columns() && has(column, row)) ++column;
            const PixelRect run = clamped(
                {first * tile_, row * tile_, column * tile_, (row + 1) * tile_}, width_, height_);
            // A rectangle ending on the row below over the same columns grows instead (a few
            // dozen rectangles at most where a piece is drawn: a plain search).
            const auto below = std::find_if(out.begin(), out.end(), [&](const PixelRect& r) {
                return r.x0 == run.x0 && r.x1 == run.x1 && r.y1 == run.y0;
            });
            if (below != out.end()) {
                below->y1 = run.y1;
            } else {
                out.push_back(run);
            }
        }
    }
}

const TileSet& TileDamage::rewrite(const TileSet* now, int width, int height) {
    const bool size_changed = last_.width() != width || last_.height() != height;
    if (now != nullptr && known_ && !size_changed) {
        region_ = *now;
        region_.add(last_);
    } else {
        region_.reset(width, height, true);
    }
    known_ = now != nullptr;
    if (now != nullptr) last_ = *now;
    return region_;
}

}  // namespace gem::gpu
