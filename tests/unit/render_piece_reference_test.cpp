// The exact reference of a whole piece against what can be known without it: a piece of one
// stone and no metal must draw exactly what the loose stone's reference draws (a second,
// independent renderer of the same rays), and a mirror of metal under a uniform sky must show
// the metal's F0, the Fresnel reflectance at normal incidence.

#include <gtest/gtest.h>

#include <cmath>

#include "optics/material.hpp"
#include "piece/metal.hpp"
#include "render/reference_render.hpp"
#include "trace_cut_stones.hpp"

namespace gem {
namespace {

RenderSettings small_picture() {
    RenderSettings s;
    s.width = s.height = 48;
    s.samples_per_pixel = 2;
    s.camera.elevation_deg = 40.0;
    s.camera.azimuth_deg = 13.0;
    s.shading.lights = {Light{{20.0, 60.0, 30.0}, false, glm::dvec3(2.0)}};
    s.shading.k_s = 0.7;  // the first reflection's and the exits' lights weighed apart
    s.shading.k_st = 1.3;
    return s;
}

TEST(PieceReference, APieceOfOneStoneIsTheLooseStonesReference) {
    const Stone stone = test::round_diamond(6.5);
    Piece piece;
    piece.name = "loose";
    piece.kinds.push_back(stone);
    piece.stones.push_back({0, {}, "centre"});
    const Environment studio = Environment::studio();
    const RenderSettings s = small_picture();
    auto loose = render_reference(stone, studio, s);
    auto whole = render_piece_reference(piece, studio, s);
    ASSERT_TRUE(loose);
    ASSERT_TRUE(whole);
    double worst = 0.0;
    int covered = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const glm::vec4 a = loose.value().at(x, y), b = whole.value().at(x, y);
            for (int c = 0; c < 4; ++c) worst = std::max(worst, double(std::abs(a[c] - b[c])));
            covered += a.w > 0.0f;
        }
    }
    EXPECT_GT(covered, 500);  // the stone is in the picture
    EXPECT_LT(worst, 1e-5);
}

TEST(PieceReference, AMirrorOfMetalUnderAUniformSkyShowsItsF0) {
    // A polished platinum plate facing up, seen straight from above.
    Piece piece;
    piece.name = "plate";
    piece.metal.f0 = metal_f0(Metal::platinum);
    piece.metal.roughness = 0.0f;
    const float h = 5.0f;
    piece.metal.positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
    piece.metal.normals.assign(4, glm::vec3(0, 1, 0));
    piece.metal.indices = {0, 2, 1, 0, 3, 2};
    RenderSettings s = small_picture();
    s.camera.elevation_deg = 90.0;
    s.camera.zoom = 2.0;  // the plate fills the picture
    s.shading.lights.clear();
    auto image = render_piece_reference(piece, Environment::uniform(glm::dvec3(1.0)), s);
    ASSERT_TRUE(image);
    const glm::vec4 centre = image.value().at(s.width / 2, s.height / 2);
    const glm::vec3 f0 = metal_f0(Metal::platinum);
    EXPECT_FLOAT_EQ(centre.w, 1.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], f0[c], 1e-3) << c;
}

}  // namespace
}  // namespace gem
