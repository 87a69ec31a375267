// The GL state a pass declares (gpu/pipeline.hpp): a pipeline sets what it states and its
// scope puts the GL back at rest; and every kind of frame the kiosk composes (each stone
// method, a piece with its metal, by visibility or facet by facet, single-sampled and
// multisampled, a still view's frames seeing the piece, glare) leaves the GL at rest. The
// state is read back from the GL (glGet), not from what the pipelines were told.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <GLES3/gl3.h>

#include "gpu/frame_composer.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/program_catalog.hpp"
#include "gpu/render_target.hpp"
#include "gpu_table_fixture.hpp"
#include "gpu_test_support.hpp"
#include "piece/piece_file.hpp"

namespace gem {
namespace {

GLint integer(GLenum what) {
    GLint v = 0;
    glGetIntegerv(what, &v);
    return v;
}

TEST(GpuPipeline, AScopeSetsWhatItStatesAndLeavesTheGlAtRest) {
    ASSERT_TRUE(gpu_test::context().ok());
    auto program = gpu::build_program("background");
    ASSERT_TRUE(program.ok()) << program.error();
    ASSERT_EQ(gpu::state_left_behind(), "") << "at rest before";
    {
        gpu::Pipeline p(&program.value(), gpu::Blend::alpha, {true, GL_LEQUAL, false, true},
                        gpu::Cull::front);
        p.colour_write = false;
        p.stencil = {true, GL_EQUAL, 7, GL_REPLACE};
        gpu::PipelineScope pass(p);
        EXPECT_EQ(integer(GL_CURRENT_PROGRAM), static_cast<GLint>(program.value().id()));
        EXPECT_TRUE(glIsEnabled(GL_BLEND));
        EXPECT_EQ(integer(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
        EXPECT_EQ(integer(GL_BLEND_DST_RGB), GL_ONE_MINUS_SRC_ALPHA);
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        EXPECT_EQ(integer(GL_DEPTH_FUNC), GL_LEQUAL);
        EXPECT_EQ(integer(GL_DEPTH_WRITEMASK), GL_FALSE);
        GLfloat range[2] = {};
        glGetFloatv(GL_DEPTH_RANGE, range);
        EXPECT_EQ(range[0], 1.0f);
        EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
        EXPECT_EQ(integer(GL_CULL_FACE_MODE), GL_FRONT);
        GLint mask[4] = {1, 1, 1, 1};
        glGetIntegerv(GL_COLOR_WRITEMASK, mask);
        EXPECT_EQ(mask[0] + mask[1] + mask[2] + mask[3], 0);
        EXPECT_TRUE(glIsEnabled(GL_STENCIL_TEST));
        EXPECT_EQ(integer(GL_STENCIL_FUNC), GL_EQUAL);
        // (The reference reads back clamped to the bound framebuffer's stencil bits: none.)
        EXPECT_EQ(integer(GL_STENCIL_PASS_DEPTH_PASS), GL_REPLACE);
        EXPECT_NE(gpu::state_left_behind(), "");

        // A step to another pipeline of the same pass changes what differs.
        pass.change(gpu::Pipeline(&program.value(), gpu::Blend::constant_alpha));
        EXPECT_EQ(integer(GL_BLEND_SRC_RGB), GL_CONSTANT_ALPHA);
        EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
        EXPECT_FALSE(glIsEnabled(GL_CULL_FACE));
        EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
        glGetFloatv(GL_DEPTH_RANGE, range);
        EXPECT_EQ(range[0], 0.0f);
    }
    EXPECT_EQ(gpu::state_left_behind(), "");
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(GpuPipeline, StateLeftBehindNamesWhatIsAwayFromRest) {
    ASSERT_TRUE(gpu_test::context().ok());
    glEnable(GL_BLEND);
    glDepthMask(GL_FALSE);
    EXPECT_EQ(gpu::state_left_behind(), "blend=1 depth_write=0");
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    EXPECT_EQ(gpu::state_left_behind(), "");
}

constexpr int kSide = 96;

// Frames of `setup`'s scene, moving (4× MSAA with glare, then single samples) and a still
// view's (its frames following the piece where the setup sees it), each checked at rest.
void expect_frames_leave_the_gl_at_rest(gpu::FrameSetup setup, const std::string& name) {
    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    ASSERT_TRUE(renderer.ok()) << name << ": " << renderer.error();
    auto target = gpu::RenderTarget::make(kSide, kSide);
    ASSERT_TRUE(target.ok()) << target.error();
    gpu::FrameView view;
    view.camera.elevation_deg = 35.0;
    view.framing_mm = renderer.value().scene_radius_mm();
    for (int samples : {4, 1}) {
        auto picture =
            gpu::HdrPicture::make(kSide, kSide, {.samples = samples, .display = {}, .glare = 0.04});
        ASSERT_TRUE(picture.ok()) << picture.error();
        for (bool visibility : {true, false}) {
            renderer.value().set_visibility_pass(visibility ? gpu::VisibilityPass::always
                                                            : gpu::VisibilityPass::off);
            picture.value().begin_frame(false);
            auto frame = gpu::compose_frame({.renderer = &renderer.value(),
                                             .view = view,
                                             .wait = gpu::FrameWait::frame,
                                             .picture = &picture.value()},
                                            target.value());
            ASSERT_TRUE(frame.ok()) << frame.error();
            ASSERT_TRUE(frame.value().scene().ok()) << frame.value().scene_error;
            EXPECT_EQ(gpu::state_left_behind(), "")
                << name << ", " << samples << " samples, visibility " << visibility;
        }
        auto still =
            gpu::draw_still_picture(renderer.value(), picture.value(), view, target.value());
        ASSERT_TRUE(still.ok()) << still.error();
        EXPECT_EQ(gpu::state_left_behind(), "") << name << ", still, " << samples << " samples";
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(GpuPipeline, EveryKindOfFrameLeavesTheGlAtRest) {
    ASSERT_TRUE(gpu_test::context().ok());
    const Environment studio = Environment::studio();
    auto halo = load_piece(std::filesystem::path(GEM_CONFIG_DIR) / "pieces" / "halo.toml");
    ASSERT_TRUE(halo) << halo.error();
    for (const char* method : {"trace", "phong"}) {
        gpu::FrameSetup setup = gpu_test::trace_setup(&halo.value(), nullptr, studio);
        setup.method = method;
        setup.trace.max_depth = 4;
        setup.cube_face = 32;
        expect_frames_leave_the_gl_at_rest(std::move(setup), std::string("halo, ") + method);
    }
    auto tables = gpu_test::round_brilliant_database();
    ASSERT_TRUE(tables.ok()) << tables.error();
    gpu::FrameSetup setup;
    setup.method = "table";
    setup.database = tables.value()->database;
    setup.stone = tables.value()->stone;
    setup.material = setup.stone.material;
    setup.table.wait_for_views = true;
    setup.environment = &studio;
    setup.cube_face = 32;
    expect_frames_leave_the_gl_at_rest(std::move(setup), "loose stone, table");
}

TEST(GpuPipeline, AUniformItsSourcesDoNotDeclareIsRecorded) {
    ASSERT_TRUE(gpu_test::context().ok());
    auto program = gpu::build_program("background");
    ASSERT_TRUE(program.ok()) << program.error();
    gpu::take_unknown_uniforms();
    const gpu::PipelineScope pass(gpu::Pipeline(&program.value()));
    program.value().set("u_environment", 0);  // declared and used
    EXPECT_TRUE(gpu::take_unknown_uniforms().empty());
    EXPECT_GE(program.value().uniform("u_environment"), 0);
    program.value().set("u_enviroment", 0);                  // misspelt
    EXPECT_EQ(program.value().uniform("u_enviroment"), -1);  // recorded once only
    const std::vector<std::string> unknown = gpu::take_unknown_uniforms();
    ASSERT_EQ(unknown.size(), 1u);
    EXPECT_EQ(unknown.front(),
              "program 'background' sets 'u_enviroment', which its sources do not declare");
    EXPECT_TRUE(gpu::take_unknown_uniforms().empty()) << "taken, so forgotten";
}

}  // namespace
}  // namespace gem
