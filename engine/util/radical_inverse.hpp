#pragma once
// The radical inverse of i in `base` (van der Corput; base 2: 0, 1/2, 1/4, 3/4, 1/8, ...): the
// digits of i mirrored behind the point. Successive values spread evenly over [0, 1), which
// the still view's sub-pixel offsets (Halton 2, 3) and its wavelengths use.

namespace gem {

inline double radical_inverse(unsigned i, unsigned base) {
    double f = 1.0, r = 0.0;
    for (; i > 0; i /= base) {
        f /= base;
        r += f * (i % base);
    }
    return r;
}

}  // namespace gem
