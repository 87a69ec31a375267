// Failure mode 3: facet edges and vertices on the GPU. A pixel ray through an edge or a vertex
// (the culet, where the pavilion mains meet; the table's rim; the girdle seen edge on) is
// where a shader's intersection code can divide by zero or pick no facet, and show NaN or a
// black pixel. Views are chosen so that many rays pass there: face-up with an odd image side
// (the centre pixel's ray runs down the axis through the table centre and the culet), face-up
// magnified on the culet, a crown view, and the girdle plane; the trace method also from
// below. Checked: every float the stone pass writes is finite, and no pixel on the stone is
// dark where the exact CPU image is bright all around it.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "failure_render.hpp"
#include "gpu_table_fixture.hpp"
#include "gpu_test_support.hpp"

namespace gem {
namespace {

constexpr int kImage = 127;  // odd: the centre pixel's ray is the stone's axis face-up
// Dark: linear luminance under 0.003 (sRGB code ≈ 10 of 255, a black speckle on a display).
// Bright: the exact image's luminance over 10× that everywhere in the pixel's 3×3
// neighbourhood, so a sub-pixel shift of an edge between the two images cannot explain it.
constexpr float kDark = 0.003f;
constexpr float kBright = 0.03f;

float shown(const glm::vec4& c) {
    return failure::luminance(glm::min(c, glm::vec4(1.0f)));
}

struct Speckles {
    int dark_where_bright = 0;  // dark on the stone, exact image bright around it
    int isolated = 0;           // of those, with no dark pixel among the 8 neighbours
    int stone = 0;              // pixels on the stone in both images
};

Speckles count_speckles(const Image& gpu, const Image& exact) {
    Speckles s;
    for (int y = 1; y + 1 < gpu.height; ++y) {
        for (int x = 1; x + 1 < gpu.width; ++x) {
            if (gpu.at(x, y).w < 0.5f || exact.at(x, y).w < 0.5f) continue;
            ++s.stone;
            if (shown(gpu.at(x, y)) >= kDark) continue;
            bool bright = true;
            bool neighbour_dark = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    bright = bright && shown(exact.at(x + dx, y + dy)) > kBright;
                    if ((dx != 0 || dy != 0) && shown(gpu.at(x + dx, y + dy)) < kDark) {
                        neighbour_dark = true;
                    }
                }
            }
            if (!bright) continue;
            ++s.dark_where_bright;
            if (!neighbour_dark) ++s.isolated;
        }
    }
    return s;
}

int non_finite(const std::vector<glm::vec4>& pixels) {
    int n = 0;
    for (const glm::vec4& p : pixels) {
        for (int c = 0; c < 4; ++c) n += std::isfinite(p[c]) ? 0 : 1;
    }
    return n;
}

struct EdgeView {
    const char* name;
    double elevation_deg;
    double azimuth_deg;
    double zoom;
    bool table;  // in the database's band (the trace method renders every view)
};

TEST(FailureEdges, NoNonFiniteValuesOrBlackSpecklesAtEdgesAndVertices) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto fx = gpu_test::round_brilliant_database();
    ASSERT_TRUE(fx.ok()) << fx.error();
    auto scene = failure::FailureScene::make(fx.value()->database);
    ASSERT_TRUE(scene.ok()) << scene.error();

    std::printf("float target: %s\n", failure::FailureScene::float_format());
    const EdgeView views[] = {{"face-up", 90.0, 0.0, 1.0, true},
                              {"face-up culet x6", 90.0, 0.0, 6.0, true},
                              {"crown 41°", 41.0, 11.25, 1.0, true},
                              {"girdle plane", 0.0, 0.0, 1.0, true},
                              {"face-down", -90.0, 0.0, 1.0, false}};
    for (const EdgeView& v : views) {
        CameraSettings cs;
        cs.elevation_deg = v.elevation_deg;
        cs.azimuth_deg = v.azimuth_deg;
        cs.zoom = v.zoom;
        auto camera =
            Camera::make(cs, bounding_radius(scene.value().stone().vertices), kImage, kImage);
        ASSERT_TRUE(camera.ok()) << camera.error();
        const Image exact = scene.value().exact(camera.value());
        auto trace = scene.value().trace(camera.value(), false);
        ASSERT_TRUE(trace.ok()) << trace.error();
        const Speckles st = count_speckles(trace.value(), exact);
        std::printf("%-17s trace: %5d stone px, %d dark where exact is bright (%d isolated)",
                    v.name, st.stone, st.dark_where_bright, st.isolated);
        // The trace method follows the exact tracer's rules per pixel: a dark pixel where the
        // exact image is bright all around is a shader fault, so none is allowed.
        EXPECT_EQ(st.dark_where_bright, 0) << v.name;
        EXPECT_GT(st.stone, 100) << v.name;
        if (v.zoom == 1.0 && v.elevation_deg == 90.0) {
            // The detector itself: one black pixel planted where the exact image is bright
            // all around must count as one isolated speckle.
            Image planted = trace.value();
            bool done = false;
            for (int y = 1; y + 1 < kImage && !done; ++y) {
                for (int x = 1; x + 1 < kImage && !done; ++x) {
                    bool bright = planted.at(x, y).w > 0.5f;
                    for (int d = 0; d < 9; ++d) {
                        bright = bright &&
                                 shown(exact.at(x + d % 3 - 1, y + d / 3 - 1)) > kBright &&
                                 shown(planted.at(x + d % 3 - 1, y + d / 3 - 1)) > kDark;
                    }
                    if (bright) {
                        planted.at(x, y) = {0.0f, 0.0f, 0.0f, 1.0f};
                        done = true;
                    }
                }
            }
            ASSERT_TRUE(done);
            const Speckles p = count_speckles(planted, exact);
            EXPECT_EQ(p.dark_where_bright, 1);
            EXPECT_EQ(p.isolated, 1);
        }
        auto trace_float = scene.value().trace_float(camera.value());
        if (trace_float) {
            EXPECT_EQ(non_finite(trace_float.value()), 0) << v.name;
        } else {
            std::printf(" (no float target: %s)", trace_float.error().c_str());
        }
        if (v.table) {
            for (const bool blend : {false, true}) {
                auto table = scene.value().table(camera.value(), blend, false);
                ASSERT_TRUE(table.ok()) << table.error();
                const Speckles s = count_speckles(table.value().image, exact);
                std::printf(
                    " | table %s (view %.1f° away): %d (%d isolated)", blend ? "blend" : "nearest",
                    glm::degrees(table.value().stats.angle_rad), s.dark_where_bright, s.isolated);
                // The table shows the stored ray-list of the nearest stored pixel, traced by
                // the same exact tracer: at a stored view (face-up is one) it may differ from
                // the exact image only where the two sample points straddle an edge, which
                // the 3×3 neighbourhood test excludes. Between stored views (crown, girdle)
                // the pattern itself differs, so dark pixels may appear where the exact image
                // is bright; those are the between-views error, not speckles, and only
                // isolated ones count: at most 0.1 % of the stone.
                const int allowed = table.value().stats.angle_rad < 1e-9 ? 0 : s.stone / 1000;
                EXPECT_LE(table.value().stats.angle_rad < 1e-9 ? s.dark_where_bright : s.isolated,
                          allowed)
                    << v.name << (blend ? " blend" : " nearest");
                auto table_float = scene.value().table_float(camera.value(), blend);
                if (table_float) {
                    EXPECT_EQ(non_finite(table_float.value()), 0) << v.name;
                }
            }
        }
        std::printf("\n");
    }
}

}  // namespace
}  // namespace gem
