// The trace method against an independent CPU image of the same scene: per pixel centre
// Camera::ray → Tracer::trace (double precision, plane clipping or the triangle BVH) →
// Shader::shade, over the environment seen directly. The GPU traces in float and reads the
// environment from a 256² cube map, so the images differ by sampling and rounding, not by
// method: coverage must agree almost everywhere, and the colour within a PSNR bound.
// The GPU's entry facet is the rasteriser's, which snaps the stone's corners to a grid of
// 2^-GL_SUBPIXEL_BITS pixel: a pixel centre closer than that to an edge of the stone's outline
// (stone or background) or between two facets may go either way. Those pixels are counted
// (edge_pixels) and left out of the PSNR; everywhere else the trace must match.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "geometry/cuts.hpp"
#include "gpu/background_pass.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/render_target.hpp"
#include "gpu/trace_method.hpp"
#include "gpu_test_support.hpp"
#include "scene/shading.hpp"
#include "trace/tracer.hpp"

namespace gem {
namespace {

constexpr int kSize = 96;
constexpr int kCubeFace = 256;

struct Case {
    const char* name = "";
    CutShape shape = CutShape::round_brilliant;
    CameraSettings camera;
    ShadingSettings shading;
    TraceSettings trace;
    std::optional<glm::dvec3> body_colour;
    glm::dvec3 absorption{0.0};
    bool as_mesh = false;  // trace a convex cut through the triangles, as a non-convex one
    gpu::ExitSearch search = gpu::ExitSearch::measured;
    std::optional<gpu::ExitSearch> expect_search;  // the search make() must choose
};

struct Comparison {
    Image gpu;              // stone over the background, as drawn
    Image cpu;              // the same, traced and shaded on the CPU
    int stone_pixels = 0;   // CPU hits
    int coverage_diff = 0;  // pixels where GPU and CPU disagree on hitting the stone
    double psnr = 0.0;      // whole image
    double psnr_stone = 0.0;
    int behind_centre = 0;  // CPU hits whose entry point lies behind the stone's centre
    int depth_diff = 0;     // pixels where the GPU's depth test and the CPU's entry disagree
    int edge_pixels = 0;    // entry facet or hit changes within the rasteriser's snapping
};

// Whether the CPU's entry (hit, facet) changes within `reach` pixels of the pixel centre.
bool entry_is_ambiguous(const Camera& camera, const Tracer& tracer, double ior,
                        const TraceSettings& settings, int x, int y, double reach,
                        RayList& scratch) {
    tracer.trace(camera.ray(x + 0.5, y + 0.5), ior, settings, scratch);
    const bool hit = scratch.hit;
    const std::uint32_t facet = scratch.reflected.facet;
    const double offsets[4][2] = {{reach, 0.0}, {-reach, 0.0}, {0.0, reach}, {0.0, -reach}};
    for (const auto& o : offsets) {
        tracer.trace(camera.ray(x + 0.5 + o[0], y + 0.5 + o[1]), ior, settings, scratch);
        if (scratch.hit != hit || (hit && scratch.reflected.facet != facet)) return true;
    }
    return false;
}

// Draws a solid magenta plane through the stone's centre (window depth 0.5: the fullscreen
// triangle's z = 0) with GL_LESS over what is in the target.
// A full-screen plane at the centre's depth in magenta: the background program over a
// uniformly magenta cube.
void draw_centre_plane(const gpu::Program& plane, const gpu::EnvironmentCube& magenta,
                       const gpu::VertexArray& empty) {
    const gpu::PipelineScope pass(gpu::Pipeline{&plane, gpu::Blend::off, {true, GL_LESS, true}});
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, magenta.texture());
    plane.set("u_environment", 0);
    plane.set("u_cam_forward",
              glm::vec3(0.0f, 0.0f, 1.0f));  // any direction: every face is magenta
    glBindVertexArray(empty.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

bool is_magenta(const glm::vec4& p) {
    return p.x > 0.99f && p.y < 0.01f && p.z > 0.99f;
}

Material material_for(const Case& c) {
    Material m = *find_material("diamond");
    if (c.body_colour) m.body_colour = *c.body_colour;
    m.absorption_per_mm = c.absorption;
    return m;
}

// Writes the GPU, CPU and difference images and says where they are.
void write_artifacts(const Comparison& r, const std::string& name) {
    const auto gpu = gpu_test::write_artifact(r.gpu, name + "_gpu");
    gpu_test::write_artifact(r.cpu, name + "_cpu");
    gpu_test::write_artifact(gpu_test::difference_image(r.gpu, r.cpu), name + "_diff");
    std::printf("[artifacts] %s (and _cpu, _diff)\n", gpu.string().c_str());
}

std::optional<Comparison> compare(const Case& c) {
    auto ctx = gpu_test::context();
    EXPECT_TRUE(ctx.ok()) << ctx.error();
    if (!ctx.ok()) return std::nullopt;
    const Material material = material_for(c);
    auto stone = make_cut(default_cut_params(c.shape), material);
    EXPECT_TRUE(stone.ok()) << stone.error();
    if (!stone.ok()) return std::nullopt;
    Stone& s = stone.value();
    if (c.as_mesh) s.convex = false;
    const double radius = bounding_radius(s.vertices);
    auto camera = Camera::make(c.camera, radius, kSize, kSize);
    EXPECT_TRUE(camera.ok()) << camera.error();
    if (!camera.ok()) return std::nullopt;
    const Environment environment = Environment::studio();
    auto cube = gpu::EnvironmentCube::from_environment(environment, kCubeFace);
    auto background = gpu::BackgroundPass::make();
    auto method = gpu::TraceMethod::make(s, c.search);
    auto target = gpu::RenderTarget::make(kSize, kSize);
    auto plane = gpu::build_program("background");
    EXPECT_TRUE(cube.ok() && background.ok() && method.ok() && target.ok() && plane.ok())
        << (!cube.ok()         ? cube.error()
            : !background.ok() ? background.error()
            : !method.ok()     ? method.error()
            : !target.ok()     ? target.error()
            : !plane.ok()      ? plane.error()
                               : "");
    if (!cube.ok() || !background.ok() || !method.ok() || !target.ok() || !plane.ok()) {
        return std::nullopt;
    }
    if (c.expect_search) {
        EXPECT_EQ(gpu::to_string(method.value().exit_search()), gpu::to_string(*c.expect_search));
    }

    gpu::StoneFrame frame;
    frame.stone = &s;
    frame.material = material;
    frame.camera = camera.value();
    frame.shading = c.shading;
    frame.environment = &cube.value();
    frame.cube_half_mm = 0.0;
    frame.scene_radius_mm = 2.0 * radius;

    Comparison r;
    // The stone alone over transparent black: alpha is the GPU's coverage.
    target.value().bind();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    auto drawn = method.value().draw(frame, c.trace);
    EXPECT_TRUE(drawn.ok()) << drawn.error();
    const Image layer = target.value().read();
    // The composite a method is used for.
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    auto back = background.value().draw(frame.camera, cube.value(), std::nullopt);
    EXPECT_TRUE(back.ok()) << back.error();
    drawn = method.value().draw(frame, c.trace);
    EXPECT_TRUE(drawn.ok()) << drawn.error();
    r.gpu = target.value().read();
    // The stone's depth: a plane through its centre hides what the stone entered behind it.
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawn = method.value().draw(frame, c.trace);
    EXPECT_TRUE(drawn.ok()) << drawn.error();
    const gpu::VertexArray empty = gpu::make_vertex_array();
    auto magenta = gpu::EnvironmentCube::from_environment(Environment::uniform({1.0, 0.0, 1.0}), 1);
    EXPECT_TRUE(magenta.ok()) << magenta.error();
    if (!magenta.ok()) return std::nullopt;
    draw_centre_plane(plane.value(), magenta.value(), empty);
    const Image cut = target.value().read();
    auto clean = gpu::gl_check("trace test");
    EXPECT_TRUE(clean.ok()) << clean.error();

    const Tracer tracer(s);
    const Shader shader(s, material, environment, c.shading);
    RayList list;
    r.cpu = Image(kSize, kSize);
    Image gpu_masked = r.gpu;
    Image cpu_masked(kSize, kSize);
    Image gpu_whole = r.gpu;
    Image cpu_whole(kSize, kSize);
    GLint subpixel_bits = 0;
    glGetIntegerv(GL_SUBPIXEL_BITS, &subpixel_bits);
    const double reach = std::ldexp(1.0, -std::max<GLint>(subpixel_bits, 4));
    RayList scratch;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const Ray ray = frame.camera.ray(x + 0.5, y + 0.5);
            tracer.trace(ray, material.index(), c.trace, list);
            const glm::dvec3 colour =
                list.hit ? shader.shade(list) : environment.radiance(ray.direction);
            r.cpu.at(x, y) = glm::vec4(glm::vec3(colour), 1.0f);
            const bool gpu_hit = layer.at(x, y).w > 0.5f;
            const bool behind =
                list.hit && glm::dot(list.reflected.origin, frame.camera.forward()) > 0.0;
            r.behind_centre += behind ? 1 : 0;
            r.depth_diff += is_magenta(cut.at(x, y)) != (!list.hit || behind) ? 1 : 0;
            r.stone_pixels += list.hit ? 1 : 0;
            r.coverage_diff += gpu_hit != list.hit ? 1 : 0;
            const bool edge = entry_is_ambiguous(frame.camera, tracer, material.index(), c.trace, x,
                                                 y, reach, scratch);
            r.edge_pixels += edge ? 1 : 0;
            // Stone-only PSNR over the pixels the CPU says are stone.
            gpu_masked.at(x, y).w = list.hit && !edge ? 1.0f : 0.0f;
            cpu_masked.at(x, y) = glm::vec4(glm::vec3(colour), list.hit && !edge ? 1.0f : 0.0f);
            gpu_whole.at(x, y).w = edge ? 0.0f : 1.0f;
            cpu_whole.at(x, y) = glm::vec4(glm::vec3(colour), edge ? 0.0f : 1.0f);
        }
    }
    r.psnr = gpu_test::psnr_srgb8(gpu_whole, cpu_whole, true);
    r.psnr_stone = gpu_test::psnr_srgb8(gpu_masked, cpu_masked, true);
    write_artifacts(r, std::string("trace_") + c.name);
    std::printf(
        "[trace %s] stone pixels %d (%d behind the centre), coverage differs %d, depth test "
        "differs %d, on an edge %d, PSNR off the edges %.2f dB, stone %.2f dB\n",
        c.name, r.stone_pixels, r.behind_centre, r.coverage_diff, r.depth_diff, r.edge_pixels,
        r.psnr, r.psnr_stone);
    return r;
}

CameraSettings three_quarter_view() {
    CameraSettings cam;
    cam.azimuth_deg = 20.0;
    cam.elevation_deg = 55.0;
    return cam;
}

TraceSettings trace_settings(int depth) {
    TraceSettings t;
    t.max_depth = depth;
    t.min_weight = 1e-3;
    return t;
}

// Two lights: a point light above and in front, and a directional one low on the side, so
// some exit rays leave through facets that face away from a light (obstruction test).
std::vector<Light> two_lights() {
    Light point;
    point.position = {8.0, 40.0, 25.0};
    point.colour = {4.0, 3.8, 3.5};
    Light side;
    side.position = {-1.0, 0.4, 0.5};
    side.directional = true;
    side.colour = {2.0, 2.2, 2.5};
    return {point, side};
}

void expect_close(const std::optional<Comparison>& r, double min_psnr, double min_stone_psnr) {
    ASSERT_TRUE(r.has_value());
    // The scene must show a stone for the comparison to mean anything.
    EXPECT_GT(r->stone_pixels, kSize * kSize / 5);
    // Float against double decides only pixel centres within a rounding error of a
    // silhouette edge differently.
    EXPECT_LE(r->coverage_diff, 3);
    // Edges within the rasteriser's snapping are a thin set: a few per cent of the stone.
    EXPECT_LT(r->edge_pixels, r->stone_pixels / 20);
    // The stone pass writes its entry point's depth: the stone shows in front of a plane
    // through its centre exactly where it was entered in front of it.
    EXPECT_GT(r->behind_centre, 0);
    EXPECT_LT(r->behind_centre, r->stone_pixels);
    EXPECT_LE(r->depth_diff, 3);
    EXPECT_GE(r->psnr, min_psnr);
    EXPECT_GE(r->psnr_stone, min_stone_psnr);
}

// Thresholds: llvmpipe measures 51.7 to 57.9 dB for the brilliant, 46.3 (whole) and 42.8 dB
// (stone) for the heart; wrong depth counting (one segment short) gives 24 to 30 dB, a heart
// whose exit rays never re-enter the cleft 33.2 / 29.8 dB.
TEST(GpuTraceMethod, PhysicalWithoutLightsMatchesCpuTracer) {
    Case c;
    c.name = "physical";
    c.camera = three_quarter_view();
    c.trace = trace_settings(8);
    expect_close(compare(c), 45.0, 44.0);
}

TEST(GpuTraceMethod, PhysicalWithTwoLightsAndAbsorptionMatchesCpuTracer) {
    Case c;
    c.name = "lights";
    c.camera = three_quarter_view();
    c.trace = trace_settings(8);
    c.shading.lights = two_lights();
    c.absorption = {0.02, 0.06, 0.12};
    expect_close(compare(c), 45.0, 44.0);
}

TEST(GpuTraceMethod, ThesisWeightsWithColourAndAlphaMatchCpuTracer) {
    Case c;
    c.name = "thesis";
    c.camera = three_quarter_view();
    c.trace = trace_settings(6);
    c.trace.weights = WeightModel::thesis_factors;
    c.trace.r_factor = 0.35;
    c.trace.t_factor = 0.6;
    c.shading.model = ShadingModel::thesis;
    c.shading.alpha = 0.6;
    c.shading.k_s = 0.8;
    c.shading.k_st = 0.5;
    c.shading.lights = two_lights();
    c.body_colour = glm::dvec3(0.85, 0.2, 0.3);
    expect_close(compare(c), 45.0, 44.0);
}

// Every way of finding a convex stone's exits, each forced (the default measures and keeps
// one).
TEST(GpuTraceMethod, FacetWalkConstantPlanesAndFoldingAllMatchCpuTracer) {
    for (gpu::ExitSearch search :
         {gpu::ExitSearch::walk, gpu::ExitSearch::constants, gpu::ExitSearch::folded}) {
        Case c;
        c.name = search == gpu::ExitSearch::walk        ? "walk"
                 : search == gpu::ExitSearch::constants ? "constants"
                                                        : "folded";  // artifact names
        c.camera = three_quarter_view();
        c.trace = trace_settings(12);
        c.shading.lights = two_lights();
        c.search = search;
        expect_close(compare(c), 45.0, 44.0);
    }
}

TEST(GpuTraceMethod, MeasuredSearchSaysWhatItChoseAndWhy) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto stone = make_cut(default_cut_params(CutShape::round_brilliant), material_for(Case{}));
    ASSERT_TRUE(stone.ok()) << stone.error();
    auto method = gpu::TraceMethod::make(stone.value());
    ASSERT_TRUE(method.ok()) << method.error();
    const auto& m = method.value();
    const gpu::ExitSearch all[] = {gpu::ExitSearch::walk, gpu::ExitSearch::constants,
                                   gpu::ExitSearch::folded};
    for (gpu::ExitSearch s : all) ASSERT_GT(m.measured_ms(s), 0.0) << gpu::to_string(s);
    for (gpu::ExitSearch s : all) {
        EXPECT_LE(m.measured_ms(m.exit_search()), m.measured_ms(s)) << gpu::to_string(s);
    }
    EXPECT_NE(m.measurement().find("folded into one wedge"), std::string::npos);
    auto forced = gpu::TraceMethod::make(stone.value(), gpu::ExitSearch::walk);
    ASSERT_TRUE(forced.ok()) << forced.error();
    EXPECT_EQ(forced.value().exit_search(), gpu::ExitSearch::walk);
    EXPECT_EQ(forced.value().measured_ms(gpu::ExitSearch::walk), 0.0);  // not measured
    EXPECT_EQ(forced.value().measurement(), "not measured");
}

TEST(GpuTraceMethod, EveryCutThatFoldsBuildsItsFoldedProgram) {
    // Each cut's constants differ (wedges, planes, guess cones, whole-number values written
    // as GLSL floats); the fold's twin (FoldedExit.*) says which cuts fold.
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    int folded = 0;
    for (CutShape shape : {CutShape::round_brilliant, CutShape::princess, CutShape::emerald,
                           CutShape::oval, CutShape::marquise, CutShape::cushion}) {
        auto stone = make_cut(default_cut_params(shape), material_for(Case{}));
        ASSERT_TRUE(stone.ok()) << stone.error();
        auto method = gpu::TraceMethod::make(stone.value(), gpu::ExitSearch::folded);
        ASSERT_TRUE(method.ok()) << to_string(shape) << ": " << method.error();
        auto target = gpu::RenderTarget::make(32, 32);
        ASSERT_TRUE(target.ok()) << target.error();
        target.value().bind();
        auto cube = gpu::EnvironmentCube::allocate(8);
        ASSERT_TRUE(cube.ok()) << cube.error();
        const double radius = bounding_radius(stone.value().vertices);
        auto camera = Camera::make(three_quarter_view(), radius, 32, 32);
        ASSERT_TRUE(camera.ok()) << camera.error();
        gpu::StoneFrame frame{
            &stone.value(), stone.value().material, camera.value(), {}, &cube.value(), 0.0,
            2.0 * radius};
        auto drawn = method.value().draw(frame, TraceSettings{});
        EXPECT_TRUE(drawn.ok()) << to_string(shape) << ": " << drawn.error();
        ++folded;
    }
    EXPECT_EQ(folded, 6);
}

TEST(GpuTraceMethod, FoldingAStoneWithOneMirrorIsRefused) {
    // The pear has one mirror (make_cut.cpp): nothing to fold by, so a forced fold fails with
    // one message and the measured choice leaves folding out.
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto pear = make_cut(default_cut_params(CutShape::pear), material_for(Case{}));
    ASSERT_TRUE(pear.ok()) << pear.error();
    auto forced = gpu::TraceMethod::make(pear.value(), gpu::ExitSearch::folded);
    ASSERT_FALSE(forced.ok());
    EXPECT_NE(forced.error().find("not mirrored"), std::string::npos) << forced.error();
    auto measured = gpu::TraceMethod::make(pear.value());
    ASSERT_TRUE(measured.ok()) << measured.error();
    EXPECT_NE(measured.value().exit_search(), gpu::ExitSearch::folded);
    EXPECT_EQ(measured.value().measured_ms(gpu::ExitSearch::folded), 0.0);
}

// The triangle path (NON_CONVEX: Moller-Trumbore in float, cleft stack) on a stone the plane
// path renders: it must be as close to the CPU's triangle BVH as the plane path is to the
// CPU's plane clipping, which isolates the heart's own differences from the method's.
TEST(GpuTraceMethod, TrianglePathOnBrilliantMatchesCpuTracer) {
    Case c;
    c.name = "brilliant_mesh";
    c.camera = three_quarter_view();
    c.trace = trace_settings(8);
    c.shading.lights = two_lights();
    c.as_mesh = true;
    expect_close(compare(c), 45.0, 44.0);
}

// The heart's worst pixels are a symmetric band whose rays leave the stone horizontally,
// onto the studio's floor/wall edge, which the filtered cube map blurs (traced in float on the
// CPU, those pixels agree with the double tracer): hence the lower bound. Traced as its two
// convex pieces (trace/convex_pieces.hpp) and through its triangles, against the CPU's BVH:
// both 46.3 dB whole and 42.8 dB on the stone on llvmpipe. Pieces whose exit rays never look
// for an entry into the other piece give 33.2 / 29.8 dB; a cut taken for a facet 10.7 / 7.3.
Case heart_case(const char* name, gpu::ExitSearch search) {
    CameraSettings cam;
    cam.azimuth_deg = 0.0;
    cam.elevation_deg = 70.0;
    Case c;
    c.name = name;
    c.shape = CutShape::heart;
    c.camera = cam;
    c.trace = trace_settings(8);
    c.shading.lights = two_lights();
    c.search = search;
    c.expect_search = search == gpu::ExitSearch::triangles ? search : gpu::ExitSearch::pieces;
    return c;
}

TEST(GpuTraceMethod, NonConvexHeartAsConvexPiecesMatchesCpuTracer) {
    expect_close(compare(heart_case("heart", gpu::ExitSearch::measured)), 40.0, 37.0);
}

TEST(GpuTraceMethod, NonConvexHeartThroughTrianglesMatchesCpuTracer) {
    expect_close(compare(heart_case("heart_triangles", gpu::ExitSearch::triangles)), 40.0, 37.0);
}

// Lights low from either side, across the cleft: a lobe hides one of them from the other lobe's
// cleft walls. llvmpipe: 54.5 dB whole, 49.3 dB on the stone as pieces; with the pieces'
// obstruction test left out (every light seen), 36.0 / 30.8.
TEST(GpuTraceMethod, NonConvexHeartHidesALightBehindItsOtherLobe) {
    for (gpu::ExitSearch search : {gpu::ExitSearch::measured, gpu::ExitSearch::triangles}) {
        Case c = heart_case("heart_lobe_shadow", search);
        c.camera.elevation_deg = 35.0;
        Light right;
        right.position = {1.0, 0.15, 0.0};
        right.directional = true;
        right.colour = {6.0, 6.0, 6.0};
        Light left = right;
        left.position.x = -1.0;
        c.shading.lights = {right, left};
        expect_close(compare(c), 50.0, 45.0);
    }
}

}  // namespace
}  // namespace gem
