// Every GPU program compiles and links as GLSL ES 3.00 on an ES 3.0 context (and those that
// need 3.10 where the context has it), and a bad shader's failure names the program and
// carries the driver's log.
#include <gtest/gtest.h>

#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/program_variants.hpp"
#include "gpu/stone_geometry.hpp"
#include "gpu_test_support.hpp"
#include "scene/lights.hpp"

namespace gem {
namespace {

TEST(GpuPrograms, ContextIsOpenGlEs3) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    GLint major = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    EXPECT_GE(major, 3) << ctx.value()->description();
}

// Every combination of the features a spec's sources test (program_variants.hpp), as
// ProgramVariants would build it; of the specular powers, pow at run time and one whole
// exponent, with lights only (without, no lobe is computed). A piece is followed under the
// physical shading only (trace_method.cpp), so SEES_PIECE never meets SHADING_THESIS.
// VISIBILITY changes only where main() finds its entry facet and where stone.vert puts its
// corners: it is built with every fire and SEES_PIECE, with no light or one, and none of the
// other shading switches, which it does not touch.
// VISIBILITY_SAMPLES (GLSL ES 3.10) comes only with VISIBILITY, as its multisampled form.
bool visibility_apart(std::uint32_t features) {
    constexpr std::uint32_t kOthers = gpu::kThesisShading | gpu::kCubeAtInfinity | gpu::kAbsorbing;
    if ((features & gpu::kVisibilitySamples) != 0 && (features & gpu::kVisibility) == 0) {
        return true;
    }
    return (features & gpu::kVisibility) != 0 &&
           ((features & kOthers) != 0 || gpu::light_count_of(features) > 1);
}

std::vector<gpu::ProgramSpec> every_variant(const gpu::ProgramSpec& spec) {
    constexpr std::uint32_t kWholePower = 60u << gpu::kSpecularPowerShift;
    const std::uint32_t switches = spec.features & ~gpu::kSpecularPowerBits;
    constexpr std::uint32_t kNever = gpu::kSeesPiece | gpu::kThesisShading;
    std::vector<gpu::ProgramSpec> variants;
    for (std::uint32_t base = 0; base <= switches; ++base) {
        if ((base & ~switches) != 0) continue;
        if (gpu::light_count_of(base) > kMaxLights) continue;
        if ((base & kNever) == kNever) continue;
        if (visibility_apart(base)) continue;
        const bool powers = (spec.features & gpu::kSpecularPowerBits) != 0 &&
                            gpu::light_count_of(base) > 0 && (base & gpu::kVisibility) == 0;
        for (std::uint32_t features : {base, base | kWholePower}) {
            if (features != base && !powers) continue;
            gpu::ProgramSpec variant = spec;
            // A program needing GLSL ES 3.10 for its own sake says so (the resolve); else its
            // features choose.
            if (spec.glsl_version == "300 es") variant.glsl_version = gpu::glsl_version(features);
            for (std::string& define : gpu::feature_defines(features)) {
                variant.defines.push_back(std::move(define));
            }
            variants.push_back(std::move(variant));
        }
    }
    return variants;
}

TEST(GpuPrograms, EveryProgramBuildsWithEveryFeature) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    const auto specs = gpu::all_program_specs();
    ASSERT_FALSE(specs.empty());
    // GLSL ES 3.10's programs on a context that has it (the frame renderer asks for them only
    // there: VisibilityTarget).
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    const bool es31 = major > 3 || (major == 3 && minor >= 1);
    int built = 0, skipped = 0;
    for (const gpu::ProgramSpec& spec : specs) {
        for (const gpu::ProgramSpec& variant : every_variant(spec)) {
            if (variant.glsl_version != "300 es" && !es31) {
                ++skipped;
                continue;
            }
            auto program = gpu::Program::build(variant);
            EXPECT_TRUE(program.ok()) << program.error();
            ++built;
        }
    }
    // table, table_non_convex and trace test six switches less the 16 combinations with both
    // SEES_PIECE and SHADING_THESIS (48 each), trace_non_convex five less 8 (24), each with
    // 0 .. 4 lights; the ring SEES_PIECE or not (2) and phong none, besides the light count.
    // Every one of these but the ring's, with 1 .. 4 lights, once more with a whole specular
    // power. And trace with VISIBILITY: its fires (4) and SEES_PIECE (2) with no light or one
    // (2); trace_non_convex its exact fire or not (2), SEES_PIECE (2), no light or one (2);
    // each of these again with VISIBILITY_SAMPLES. The ring with VISIBILITY (marking the
    // samples it takes), SEES_PIECE or not, no light or one (4).
    EXPECT_EQ(built + skipped, static_cast<int>(specs.size()) - 6 +
                                   5 * (48 + 48 + 48 + 24 + 2 + 1) + 4 * (48 + 48 + 48 + 24 + 1) +
                                   2 * (16 + 8) + 4);
    EXPECT_EQ(skipped, es31 ? 0 : 16 + 8 + 1);  // and the resolve's one
    auto clean = gpu::gl_check("building every program");
    EXPECT_TRUE(clean.ok()) << clean.error();
}

TEST(GpuPrograms, FeatureDefinesFollowTheBits) {
    EXPECT_TRUE(gpu::feature_defines(0).empty());
    EXPECT_EQ(gpu::feature_defines(gpu::kThesisShading | gpu::kTwoViews),
              (std::vector<std::string>{"SHADING_THESIS", "TWO_VIEWS"}));
    EXPECT_EQ(gpu::feature_defines(gpu::kCubeAtInfinity | gpu::kFireFirstOrder | gpu::kFireExact),
              (std::vector<std::string>{"CUBE_AT_INFINITY", "FIRE_FIRST_ORDER", "FIRE_EXACT"}));
    EXPECT_EQ(gpu::feature_defines(gpu::kTwoViews | gpu::light_count_feature(3)),
              (std::vector<std::string>{"TWO_VIEWS", "LIGHT_COUNT 3"}));
    EXPECT_EQ(gpu::light_count_of(gpu::kThesisShading | gpu::light_count_feature(4)), 4);
    EXPECT_EQ(gpu::feature_defines(gpu::light_count_feature(2) | gpu::specular_power_feature(60)),
              (std::vector<std::string>{"LIGHT_COUNT 2", "SPECULAR_POWER 60"}));
    EXPECT_EQ(gpu::feature_defines(gpu::kAbsorbing | gpu::kSeesPiece | gpu::light_count_feature(1)),
              (std::vector<std::string>{"ABSORBING", "LIGHT_COUNT 1", "SEES_PIECE"}));
}

TEST(GpuPrograms, OnlyAWholeSpecularExponentIsCompiledIn) {
    EXPECT_EQ(gpu::specular_power_of(gpu::specular_power_feature(60.0)), 60);
    EXPECT_EQ(gpu::specular_power_of(gpu::specular_power_feature(1.0)), 1);
    EXPECT_EQ(gpu::specular_power_of(gpu::specular_power_feature(1023.0)), 1023);
    EXPECT_EQ(gpu::specular_power_feature(60.5), 0u);  // pow at run time
    EXPECT_EQ(gpu::specular_power_feature(0.5), 0u);
    EXPECT_EQ(gpu::specular_power_feature(0.0), 0u);
    EXPECT_EQ(gpu::specular_power_feature(1024.0), 0u);  // more than the bits hold
    EXPECT_EQ(gpu::specular_power_feature(2000.0), 0u);
}

TEST(GpuPrograms, StoneBlockHasTheLayoutTheUploadWrites) {
    // stone.glsl's std140 block and StoneGeometry's struct must agree to the byte in every
    // program that reads the facets.
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    int readers = 0;
    for (const gpu::ProgramSpec& spec : gpu::all_program_specs()) {
        auto program = gpu::Program::build(spec);
        ASSERT_TRUE(program.ok()) << program.error();
        const GLuint index = glGetUniformBlockIndex(program.value().id(), "StoneFacets");
        if (index == GL_INVALID_INDEX) continue;
        GLint bytes = 0;
        glGetActiveUniformBlockiv(program.value().id(), index, GL_UNIFORM_BLOCK_DATA_SIZE, &bytes);
        EXPECT_EQ(static_cast<std::size_t>(bytes), gpu::stone_block_bytes()) << spec.name;
        GLint limit = 0;
        glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &limit);
        EXPECT_LE(bytes, 16384) << "more than OpenGL ES 3.0 guarantees";
        EXPECT_LE(bytes, limit) << spec.name;
        ++readers;
    }
    EXPECT_GE(readers, 5);  // table, trace (both variants each) and phong
}

TEST(GpuPrograms, MissingChunkIsNamed) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    auto program = gpu::Program::build({"broken", {"fullscreen.vert"}, {"no_such.frag"}, {}});
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().find("no_such.frag"), std::string::npos) << program.error();
    EXPECT_NE(program.error().find("'broken'"), std::string::npos) << program.error();
}

TEST(GpuPrograms, CompileErrorCarriesTheLog) {
    auto ctx = gpu_test::context();
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    // A define that turns a uniform's declaration into a syntax error.
    auto program = gpu::Program::build({"undeclared",
                                        {"fullscreen.vert"},
                                        {"camera.glsl", "background.frag"},
                                        {"u_environment 1.0 +"}});
    ASSERT_FALSE(program.ok());
    EXPECT_NE(program.error().find("fragment shader camera.glsl+background.frag"),
              std::string::npos)
        << program.error();
    EXPECT_NE(program.error().find("does not compile"), std::string::npos) << program.error();
}

}  // namespace
}  // namespace gem
