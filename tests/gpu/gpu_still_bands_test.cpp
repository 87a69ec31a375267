// Where a still frame's bands split the rows (gpu/still_bands.hpp): evenly at first, then by
// the last frame's costs, each band's cost taken as spread evenly over its rows; every row in
// exactly one band. The edges are worked out by hand below.
#include <gtest/gtest.h>

#include "gpu/still_bands.hpp"

namespace gem::gpu {
namespace {

const PixelRect kContent{10, 100, 30, 200};  // 100 rows, from row 100

TEST(StillBands, AtFirstTheRowsAreSplitEvenly) {
    StillBands b;
    b.start(4);
    EXPECT_EQ(b.bands(), 4);
    for (int k = 0; k < 4; ++k) {
        const PixelRect r = b.rows(kContent, k);
        EXPECT_EQ(r.x0, 10);
        EXPECT_EQ(r.x1, 30);
        EXPECT_EQ(r.y0, 100 + 25 * k);
        EXPECT_EQ(r.y1, 125 + 25 * k);
    }
}

TEST(StillBands, TheNextFrameIsSplitByTheLastOnesCosts) {
    StillBands b;
    b.start(2);  // rows 100-149 and 150-199
    b.measured(0, 10.0);
    b.measured(1, 30.0);
    EXPECT_EQ(b.dearest_ms(), 30.0);
    // The whole 40 ms; two bands of 20: the first takes all of band 0 (10 ms, 50 rows) and a
    // third of band 1 (10 of its 30 ms: 16.7 rows), so its edge is at 66.7 rows, rounded 67.
    b.start(2);
    EXPECT_EQ(b.rows(kContent, 0).y0, 100);
    EXPECT_EQ(b.rows(kContent, 0).y1, 167);
    EXPECT_EQ(b.rows(kContent, 1).y0, 167);
    EXPECT_EQ(b.rows(kContent, 1).y1, 200);
    // Four bands of 10 ms from the same costs: band 0 whole (50 rows), then band 1's 50 rows in
    // thirds: 66.7, 83.3.
    b.start(4);
    EXPECT_EQ(b.rows(kContent, 0).y1, 150);
    EXPECT_EQ(b.rows(kContent, 1).y1, 167);
    EXPECT_EQ(b.rows(kContent, 2).y1, 183);
    EXPECT_EQ(b.rows(kContent, 3).y1, 200);
}

TEST(StillBands, AFrameNotMeasuredWholeLeavesTheSplitEven) {
    StillBands b;
    b.start(2);
    b.measured(0, 10.0);  // a touch came before band 1
    b.start(2);
    EXPECT_EQ(b.rows(kContent, 0).y1, 150);
}

TEST(StillBands, EveryRowIsInOneBandEvenWithFewerRowsThanBands) {
    StillBands b;
    b.start(3);
    b.measured(0, 1000.0);
    b.measured(1, 1e-3);
    b.measured(2, 1e-3);
    for (const int rows : {1, 2, 3, 7, 100}) {
        b.start(8);
        const PixelRect content{0, 0, 4, rows};
        int next = 0;
        for (int k = 0; k < 8; ++k) {
            const PixelRect r = b.rows(content, k);
            EXPECT_EQ(r.y0, next) << rows << " rows, band " << k;
            EXPECT_GE(r.y1, r.y0);
            if (k < rows) {
                EXPECT_GT(r.y1, r.y0) << rows << " rows, band " << k;
            }
            next = r.y1;
        }
        EXPECT_EQ(next, rows);
    }
}

}  // namespace
}  // namespace gem::gpu
