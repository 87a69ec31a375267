// What a pass over the piece's box costs on this GL at the least, beside what the picture's
// finishing passes cost there (bench_picture): over the box the kiosk's start view rewrites
// (960×1080 of a 1920×1080 picture), the median ms of 15 passes each, each bounded by glFinish,
// the passes in turn, three rounds:
//   - a constant written to an sRGB8 picture (a pass's floor: rasterising and writing);
//   - one RGBA16F texel fetched and written there (the tone pass's floor: it also reads the
//     glare and applies the curve);
//   - the 4× MSAA RGBA16F picture resolved by glBlitFramebuffer, as HdrPicture resolves it,
//     and by a shader averaging the four samples of a multisampled texture (OpenGL ES 3.1),
//     which is what folding the resolve into a later pass would cost that pass.
//
//   bench_pass_floor

#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include <GLES3/gl31.h>

#include "bench_support.hpp"
#include "gpu/egl_context.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/program.hpp"
#include "util/elapsed.hpp"

namespace {

constexpr int kWidth = 1920, kHeight = 1080;
constexpr int kBox[4] = {480, 0, 960, 1080};  // x, y, width, height

const std::vector<gem::gpu::ShaderSource> kSources = {
    {"floor_constant.frag", R"(out vec4 o_colour;
void main() { o_colour = vec4(0.2, 0.4, 0.6, 1.0); })"},
    {"floor_fetch.frag", R"(uniform sampler2D u_scene;
out vec4 o_colour;
void main() { o_colour = texelFetch(u_scene, ivec2(gl_FragCoord.xy), 0); })"},
    {"floor_resolve.frag", R"(uniform highp sampler2DMS u_samples;
out vec4 o_colour;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    o_colour = 0.25 * (texelFetch(u_samples, p, 0) + texelFetch(u_samples, p, 1) +
                       texelFetch(u_samples, p, 2) + texelFetch(u_samples, p, 3));
})"},
};

gem::gpu::Program program(const char* fragment) {
    return gem::bench::must("bench_pass_floor",
                            gem::gpu::Program::build({.name = fragment,
                                                      .vertex = {"fullscreen.vert"},
                                                      .fragment = {fragment},
                                                      .defines = {},
                                                      .features = 0,
                                                      .glsl_version = "310 es",
                                                      .sources = &kSources}));
}

double median_ms(const std::function<void()>& pass) {
    std::vector<double> ms;
    for (int i = 0; i < 15; ++i) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        pass();
        glFinish();
        ms.push_back(gem::ms_since(start));
    }
    return gem::bench::median(ms);
}

}  // namespace

int main() {
    using namespace gem::gpu;
    auto context = gem::bench::must("bench_pass_floor", EglContext::headless());
    // The picture the passes write, and the scene they read, resolved and multisampled.
    const Texture picture = make_texture_2d(GL_SRGB8_ALPHA8, kWidth, kHeight, GL_NEAREST);
    const Framebuffer to_picture = make_framebuffer_with(picture.get());
    const Texture resolved = make_texture_2d(GL_RGBA16F, kWidth, kHeight, GL_NEAREST);
    const Framebuffer to_resolved = make_framebuffer_with(resolved.get());
    const Renderbuffer samples_rb = make_renderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, samples_rb.get());
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA16F, kWidth, kHeight);
    const Framebuffer from_rb = make_framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, from_rb.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              samples_rb.get());
    const Texture samples_tex = make_texture();
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, samples_tex.get());
    glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA16F, kWidth, kHeight, GL_TRUE);
    const Framebuffer from_tex = make_framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, from_tex.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE,
                           samples_tex.get(), 0);
    for (GLuint f : {from_rb.get(), from_tex.get(), to_resolved.get()}) {
        glBindFramebuffer(GL_FRAMEBUFFER, f);
        glClearColor(0.3f, 0.5f, 0.7f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const Program constant = program("floor_constant.frag");
    const Program fetch = program("floor_fetch.frag");
    const Program resolve = program("floor_resolve.frag");
    const VertexArray no_attributes = make_vertex_array();

    // One triangle over the box, scissored, into `target`, reading `texture` on unit 0.
    const auto draw = [&](const Program& p, GLuint target, GLenum kind, GLuint texture,
                          const char* sampler) {
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, kWidth, kHeight);
        glEnable(GL_SCISSOR_TEST);
        glScissor(kBox[0], kBox[1], kBox[2], kBox[3]);
        const PipelineScope pass(Pipeline{&p});
        if (texture != 0) {
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(kind, texture);
            p.set(sampler, 0);
        }
        glBindVertexArray(no_attributes.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    };
    const auto blit = [&](GLuint from) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to_resolved.get());
        const int x1 = kBox[0] + kBox[2], y1 = kBox[1] + kBox[3];
        glBlitFramebuffer(kBox[0], kBox[1], x1, y1, kBox[0], kBox[1], x1, y1, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    };
    std::printf("a pass over %dx%d of %dx%d, median ms of 15, three rounds in turn\n", kBox[2],
                kBox[3], kWidth, kHeight);
    std::printf("%-8s %10s %10s %12s %12s %12s\n", "round", "constant", "one fetch", "blit (rb)",
                "blit (tex)", "shader");
    for (int round = 1; round <= 3; ++round) {
        const double c = median_ms([&] { draw(constant, to_picture.get(), 0, 0, nullptr); });
        const double f = median_ms(
            [&] { draw(fetch, to_picture.get(), GL_TEXTURE_2D, resolved.get(), "u_scene"); });
        const double b_rb = median_ms([&] { blit(from_rb.get()); });
        const double b_tex = median_ms([&] { blit(from_tex.get()); });
        const double s = median_ms([&] {
            draw(resolve, to_resolved.get(), GL_TEXTURE_2D_MULTISAMPLE, samples_tex.get(),
                 "u_samples");
        });
        std::printf("%-8d %10.2f %10.2f %12.2f %12.2f %12.2f\n", round, c, f, b_rb, b_tex, s);
    }
    return 0;
}
