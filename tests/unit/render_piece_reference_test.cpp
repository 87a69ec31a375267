// The exact reference of a whole piece against what can be known without it: a piece of one
// stone and no metal must draw exactly what the loose stone's reference draws (a second,
// independent renderer of the same rays), and a mirror of metal under a uniform sky must show
// the metal's F0, the Fresnel reflectance at normal incidence, and a rough one the reflectance
// of the white furnace. Two stones that see only the
// metal (PieceSight::metal_only) each draw what they draw alone, and differ where they see each
// other (PieceSight::everything); so does a metal that sees only the environment
// (PieceSight::metal_sees_environment) beside a wall it would otherwise see.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cpu/reference_render.hpp"
#include "optics/material.hpp"
#include "optics/microfacet.hpp"
#include "piece/metal.hpp"
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

// A 10 mm square plate of `metal` facing up, and no stone.
Piece plate(Metal metal, float roughness) {
    Piece piece;
    piece.name = "plate";
    piece.metal.f0 = metal_f0(metal);
    piece.metal.roughness = roughness;
    const float h = 5.0f;
    piece.metal.positions = {{-h, 0, -h}, {h, 0, -h}, {h, 0, h}, {-h, 0, h}};
    piece.metal.normals.assign(4, glm::vec3(0, 1, 0));
    piece.metal.indices = {0, 2, 1, 0, 3, 2};
    return piece;
}

// Seen straight from above, the plate filling the picture, without lights.
RenderSettings from_above() {
    RenderSettings s = small_picture();
    s.camera.elevation_deg = 90.0;
    s.camera.zoom = 2.0;
    s.shading.lights.clear();
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
    const Piece piece = plate(Metal::platinum, 0.0f);
    const RenderSettings s = from_above();
    auto image = render_piece_reference(piece, Environment::uniform(glm::dvec3(1.0)), s);
    ASSERT_TRUE(image);
    const glm::vec4 centre = image.value().at(s.width / 2, s.height / 2);
    const glm::vec3 f0 = metal_f0(Metal::platinum);
    EXPECT_FLOAT_EQ(centre.w, 1.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], f0[c], 1e-3) << c;
}

// The same plate, rough (roughness 0.25, the pieces' default), in the white furnace's uniform
// sky: on average it reflects F0·scale + bias of the environment BRDF, which the microfacet
// test holds to quadrature. 16 × 16 pixels of 16 samples each are averaged against the noise.
TEST(PieceReference, ARoughPlateUnderAUniformSkyReflectsItsEnvironmentBrdf) {
    const Piece piece = plate(Metal::yellow_gold, 0.25f);
    RenderSettings s = from_above();
    s.samples_per_pixel = 16;
    auto image = render_piece_reference(piece, Environment::uniform(glm::dvec3(1.0)), s);
    ASSERT_TRUE(image);
    glm::dvec3 mean(0.0);
    for (int y = s.height / 2 - 8; y < s.height / 2 + 8; ++y) {
        for (int x = s.width / 2 - 8; x < s.width / 2 + 8; ++x) {
            mean += glm::dvec3(image.value().at(x, y)) / 256.0;
        }
    }
    const EnvironmentBrdf e = environment_brdf(1.0, 0.25);
    const glm::vec3 f0 = metal_f0(Metal::yellow_gold);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], f0[c] * e.scale + e.bias, 3e-3) << c;
}

// Two diamonds side by side, 0.6 mm apart, each drawn in a piece of its own and both in one.
// Every piece holds one metal vertex and no triangles, so the camera frames the same sphere.
TEST(PieceReference, StonesThatSeeOnlyTheMetalDrawWhatEachDrawsAlone) {
    const Stone stone = test::round_diamond(3.0);
    auto piece_of = [&](std::vector<glm::dvec3> at) {
        Piece piece;
        piece.name = "pair";
        piece.kinds.push_back(stone);
        for (const glm::dvec3& p : at) piece.stones.push_back({0, {glm::dmat3(1.0), p}, "stone"});
        piece.metal.positions = {glm::vec3(0.0f, 0.0f, 4.0f)};
        return piece;
    };
    const glm::dvec3 left(-1.8, 0.0, 0.0), right(1.8, 0.0, 0.0);
    const Environment studio = Environment::studio();
    RenderSettings s = small_picture();
    s.camera.azimuth_deg = 0.0;  // the pair across the picture, neither hiding the other
    auto render = [&](const Piece& piece, PieceSight sight) {
        auto image = render_piece_reference(piece, studio, s, nullptr, sight);
        EXPECT_TRUE(image) << image.error();
        return image ? image.value() : Image{};
    };
    const Image pair_blind = render(piece_of({left, right}), PieceSight::metal_only);
    const Image pair = render(piece_of({left, right}), PieceSight::everything);
    const Image alone_left = render(piece_of({left}), PieceSight::everything);
    const Image alone_right = render(piece_of({right}), PieceSight::everything);
    double blind_worst = 0.0, seeing_mean = 0.0;
    int covered = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const glm::vec4 l = alone_left.at(x, y), r = alone_right.at(x, y);
            if (l.w < 1.0f && r.w < 1.0f) continue;
            const glm::vec4 alone = l.w >= 1.0f ? l : r;
            const glm::vec4 blind = pair_blind.at(x, y), seeing = pair.at(x, y);
            for (int c = 0; c < 3; ++c) {
                blind_worst = std::max(blind_worst, double(std::abs(blind[c] - alone[c])));
                seeing_mean += std::abs(seeing[c] - alone[c]) / 3.0;
            }
            ++covered;
        }
    }
    ASSERT_GT(covered, 200);
    EXPECT_LT(blind_worst, 1e-5);
    EXPECT_GT(seeing_mean / covered, 1e-3);  // each stone's exits meet the other
}

// A rough plate facing up beside a wall of metal standing on its edge, seen from above (the
// wall edge-on, so not itself in the picture), under the white furnace's sky with a light. A
// metal that sees only the environment and the lights (PieceSight::metal_sees_environment, as
// the GPU's metal) draws the plate as the plate alone draws it; the truth differs beside the
// wall, which takes some of the plate's reflections and gives back what it sees.
TEST(PieceReference, AMetalThatSeesOnlyTheEnvironmentDrawsWhatItDrawsAlone) {
    auto piece_of = [](bool wall) {
        Piece piece = plate(Metal::platinum, 0.25f);
        // The wall's corners are there either way, so the camera frames the same sphere.
        const glm::vec3 corners[4] = {{2, 0, -5}, {2, 0, 5}, {2, 6, 5}, {2, 6, -5}};
        for (const glm::vec3& c : corners) {
            piece.metal.positions.push_back(c);
            piece.metal.normals.push_back(glm::vec3(-1, 0, 0));
        }
        if (wall) piece.metal.indices.insert(piece.metal.indices.end(), {4, 5, 6, 4, 6, 7});
        return piece;
    };
    RenderSettings s = from_above();
    s.samples_per_pixel = 16;
    s.shading.lights = {Light{{-20.0, 60.0, 10.0}, false, glm::dvec3(2.0)}};
    const Environment sky = Environment::uniform(glm::dvec3(1.0));
    auto render = [&](const Piece& piece, PieceSight sight) {
        auto image = render_piece_reference(piece, sky, s, nullptr, sight);
        EXPECT_TRUE(image) << image.error();
        return image ? image.value() : Image{};
    };
    const Image alone = render(piece_of(false), PieceSight::everything);
    const Image blind = render(piece_of(true), PieceSight::metal_sees_environment);
    const Image truth = render(piece_of(true), PieceSight::everything);
    double blind_worst = 0.0, truth_mean = 0.0;
    int covered = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const glm::vec4 a = alone.at(x, y);
            if (a.w < 1.0f) continue;
            for (int c = 0; c < 3; ++c) {
                blind_worst = std::max(blind_worst, double(std::abs(blind.at(x, y)[c] - a[c])));
                truth_mean += std::abs(truth.at(x, y)[c] - a[c]) / 3.0;
            }
            ++covered;
        }
    }
    ASSERT_GT(covered, 500);
    EXPECT_LT(blind_worst, 1e-5);
    std::printf("the plate beside the wall against the plate alone: %.4f a channel\n",
                truth_mean / covered);
    EXPECT_GT(truth_mean / covered, 1e-3);  // the plate's reflections meet the wall
}

}  // namespace
}  // namespace gem
