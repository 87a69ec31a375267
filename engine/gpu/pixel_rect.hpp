#pragma once
// Rectangles of pixels in a framebuffer's own coordinates (GL's: x right, y up from the
// bottom row), for drawing only where a picture changed: the passes after the scene run over
// the rectangles of the tiles the piece covers (tile_set.hpp, hdr_picture.hpp), each glare
// level over what those reach (affected_by(), read_by()).

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

namespace gem::gpu {

// [x0, x1) × [y0, y1); empty when either side is not positive.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    static PixelRect whole(int width, int height) { return {0, 0, width, height}; }
    int width() const { return std::max(x1 - x0, 0); }
    int height() const { return std::max(y1 - y0, 0); }
    bool empty() const { return width() == 0 || height() == 0; }
    long area() const { return static_cast<long>(width()) * height(); }
    bool operator==(const PixelRect&) const = default;
};

// The smallest rectangle holding both (an empty one adds nothing).
inline PixelRect united(const PixelRect& a, const PixelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

// The pixels in both (none: an empty rectangle).
inline PixelRect intersected(const PixelRect& a, const PixelRect& b) {
    const PixelRect c{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1),
                      std::min(a.y1, b.y1)};
    return c.empty() ? PixelRect{} : c;
}

inline PixelRect clamped(const PixelRect& r, int width, int height) {
    return intersected(r, PixelRect::whole(width, height));
}

// One side of affected_by(): the output texels [lo, hi) whose taps reach input texels [a, b).
// An output texel j samples the input at x = (j + 0.5) · scale + o, o in [reach_lo, reach_hi]
// (in input texels), with bilinear filtering, so it reads the input texels from
// floor(x_lo − 0.5) to floor(x_hi + 0.5). It is affected when that range meets [a, b):
// (j + 0.5) · scale + reach_hi + 0.5 ≥ a and (j + 0.5) · scale + reach_lo − 0.5 < b. One texel
// more on each side keeps float rounding in the shaders' own coordinates on the safe side.
inline void affected_side(int a, int b, double scale, double reach_lo, double reach_hi, int& lo,
                          int& hi) {
    lo = static_cast<int>(std::ceil((a - reach_hi - 0.5) / scale - 0.5)) - 1;
    hi = static_cast<int>(std::ceil((b - reach_lo + 0.5) / scale - 0.5)) + 1;
}

// The other way round: the input texels [lo, hi) that output texels [a, b) read, for the same
// pass (output texel j reads input texels floor(x_lo − 0.5) to floor(x_hi + 0.5)), one texel
// more on each side as above.
inline void read_side(int a, int b, double scale, double reach_lo, double reach_hi, int& lo,
                      int& hi) {
    lo = static_cast<int>(std::floor((a + 0.5) * scale + reach_lo - 0.5)) - 1;
    hi = static_cast<int>(std::floor((b - 0.5) * scale + reach_hi + 0.5)) + 2;
}

// `side` (affected_side or read_side) along x and y, clamped to [0, size).
template <class Side>
PixelRect sides(const PixelRect& from, glm::dvec2 scale, double reach_lo, double reach_hi,
                glm::ivec2 size, Side side) {
    if (from.empty()) return {};
    PixelRect r;
    side(from.x0, from.x1, scale.x, reach_lo, reach_hi, r.x0, r.x1);
    side(from.y0, from.y1, scale.y, reach_lo, reach_hi, r.y0, r.y1);
    r = {std::clamp(r.x0, 0, size.x), std::clamp(r.y0, 0, size.y), std::clamp(r.x1, 0, size.x),
         std::clamp(r.y1, 0, size.y)};
    return r.empty() ? PixelRect{} : r;
}

// The texels of an output of `size` that read anything in `input` (in input texels), for a
// pass sampling at `scale` input texels per output texel with taps from `reach_lo` to
// `reach_hi` input texels about the centre, bilinear.
inline PixelRect affected_by(const PixelRect& input, glm::dvec2 scale, double reach_lo,
                             double reach_hi, glm::ivec2 size) {
    return sides(input, scale, reach_lo, reach_hi, size, affected_side);
}

// The texels of an input of `size` that the output texels in `output` read, for a pass as
// affected_by()'s: where the input must hold this frame's values before the pass runs there.
inline PixelRect read_by(const PixelRect& output, glm::dvec2 scale, double reach_lo,
                         double reach_hi, glm::ivec2 size) {
    return sides(output, scale, reach_lo, reach_hi, size, read_side);
}

}  // namespace gem::gpu
