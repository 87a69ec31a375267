// What a pass over the piece's box costs on this GL at the least, beside what the picture's
// finishing passes cost there (bench_picture): over the box the kiosk's start view rewrites
// (960×1080 of a 1920×1080 picture), the median ms of 15 passes each, each bounded by glFinish,
// the passes in turn, three rounds:
//   - a constant written to an sRGB8 picture (a pass's floor: rasterising and writing);
//   - one RGBA16F texel fetched and written there (the tone pass's floor: it also reads the
//     glare and applies the curve);
//   - the 4× MSAA RGBA16F picture resolved by glBlitFramebuffer, as HdrPicture resolves it,
//     and by a shader averaging the four samples of a multisampled texture (OpenGL ES 3.1),
//     which is what folding the resolve into a later pass would cost that pass;
//   - the fetch and the blit again over the same box as 32-pixel tiles, one scissored draw or
//     blit per 32-row strip and per 32×32 tile, and the fetch over every tile as two triangles
//     in one draw (rect_draw.hpp), then over every other tile so: what drawing only a piece's
//     own tiles (tile_set.hpp) pays a draw, and what half the pixels save.
//
//   bench_pass_floor

#include <algorithm>
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
    {"floor_quads.vert", R"(layout(location = 0) in vec2 a_position;
void main() { gl_Position = vec4(a_position, 0.0, 1.0); })"},
    {"floor_resolve.frag", R"(uniform highp sampler2DMS u_samples;
out vec4 o_colour;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    o_colour = 0.25 * (texelFetch(u_samples, p, 0) + texelFetch(u_samples, p, 1) +
                       texelFetch(u_samples, p, 2) + texelFetch(u_samples, p, 3));
})"},
};

gem::gpu::Program program(const char* fragment, const char* vertex = "fullscreen.vert") {
    return gem::bench::must("bench_pass_floor", gem::gpu::Program::build({.name = fragment,
                                                                          .vertex = {vertex},
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
    // The box whole, or cut into pieces of `w` × `h` pixels (scissors or blits, one each).
    struct Piece {
        int x, y, w, h;
    };
    const auto pieces = [](int w, int h) {
        std::vector<Piece> out;
        for (int y = kBox[1]; y < kBox[1] + kBox[3]; y += h) {
            for (int x = kBox[0]; x < kBox[0] + kBox[2]; x += w) {
                out.push_back(
                    {x, y, std::min(w, kBox[0] + kBox[2] - x), std::min(h, kBox[1] + kBox[3] - y)});
            }
        }
        return out;
    };
    const std::vector<Piece> box = pieces(kBox[2], kBox[3]);
    const std::vector<Piece> strips = pieces(kBox[2], 32);
    const std::vector<Piece> tiles = pieces(32, 32);
    const auto draw = [&](const Program& p, GLuint target, GLenum kind, GLuint texture,
                          const char* sampler, const std::vector<Piece>& over) {
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, kWidth, kHeight);
        glEnable(GL_SCISSOR_TEST);
        const PipelineScope pass(Pipeline{&p});
        if (texture != 0) {
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(kind, texture);
            p.set(sampler, 0);
        }
        glBindVertexArray(no_attributes.get());
        for (const Piece& r : over) {
            glScissor(r.x, r.y, r.w, r.h);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        glDisable(GL_SCISSOR_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    };
    // The pieces as two triangles each, in one draw.
    const Program fetch_quads = program("floor_fetch.frag", "floor_quads.vert");
    const VertexArray quads = make_vertex_array();
    const Buffer quad_buffer = make_buffer();
    const auto quads_of = [&](const std::vector<Piece>& over) {
        std::vector<float> xy;
        for (const Piece& r : over) {
            const float x0 = 2.0f * r.x / kWidth - 1.0f, x1 = 2.0f * (r.x + r.w) / kWidth - 1.0f;
            const float y0 = 2.0f * r.y / kHeight - 1.0f, y1 = 2.0f * (r.y + r.h) / kHeight - 1.0f;
            xy.insert(xy.end(), {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1});
        }
        return xy;
    };
    // Every other tile, as a checkerboard: half the box.
    std::vector<Piece> half;
    for (const Piece& p : tiles) {
        if (((p.x - kBox[0]) / 32 + (p.y - kBox[1]) / 32) % 2 == 0) half.push_back(p);
    }
    const std::vector<float> tile_quads = quads_of(tiles);
    const std::vector<float> half_quads = quads_of(half);
    glBindVertexArray(quads.get());
    glBindBuffer(GL_ARRAY_BUFFER, quad_buffer.get());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
    const auto draw_quads = [&](const std::vector<float>& xy) {
        glBindBuffer(GL_ARRAY_BUFFER, quad_buffer.get());
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(xy.size() * sizeof(float)), xy.data(),
                     GL_STREAM_DRAW);
        glBindFramebuffer(GL_FRAMEBUFFER, to_picture.get());
        glViewport(0, 0, kWidth, kHeight);
        const PipelineScope pass(Pipeline{&fetch_quads});
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, resolved.get());
        fetch_quads.set("u_scene", 0);
        glBindVertexArray(quads.get());
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(xy.size() / 2));
        glBindVertexArray(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    };
    const auto blit = [&](GLuint from, const std::vector<Piece>& over) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to_resolved.get());
        for (const Piece& r : over) {
            glBlitFramebuffer(r.x, r.y, r.x + r.w, r.y + r.h, r.x, r.y, r.x + r.w, r.y + r.h,
                              GL_COLOR_BUFFER_BIT, GL_NEAREST);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    };
    std::printf("a pass over %dx%d of %dx%d, median ms of 15, three rounds in turn\n", kBox[2],
                kBox[3], kWidth, kHeight);
    std::printf("%-8s %10s %10s %12s %12s %12s %14s %14s %15s %14s %14s %14s\n", "round",
                "constant", "one fetch", "blit (rb)", "blit (tex)", "shader", "fetch, strips",
                "fetch, tiles", "tiles, one draw", "half of them", "blit, strips", "blit, tiles");
    for (int round = 1; round <= 3; ++round) {
        const double c = median_ms([&] { draw(constant, to_picture.get(), 0, 0, nullptr, box); });
        const auto fetch_over = [&](const std::vector<Piece>& over) {
            return median_ms([&] {
                draw(fetch, to_picture.get(), GL_TEXTURE_2D, resolved.get(), "u_scene", over);
            });
        };
        const double f = fetch_over(box);
        const double b_rb = median_ms([&] { blit(from_rb.get(), box); });
        const double b_tex = median_ms([&] { blit(from_tex.get(), box); });
        const double s = median_ms([&] {
            draw(resolve, to_resolved.get(), GL_TEXTURE_2D_MULTISAMPLE, samples_tex.get(),
                 "u_samples", box);
        });
        const double f_strips = fetch_over(strips);
        const double f_tiles = fetch_over(tiles);
        const double b_strips = median_ms([&] { blit(from_rb.get(), strips); });
        const double b_tiles = median_ms([&] { blit(from_rb.get(), tiles); });
        std::printf(
            "%-8d %10.2f %10.2f %12.2f %12.2f %12.2f %14.2f %14.2f %15.2f %14.2f %14.2f %14.2f\n",
            round, c, f, b_rb, b_tex, s, f_strips, f_tiles,
            median_ms([&] { draw_quads(tile_quads); }), median_ms([&] { draw_quads(half_quads); }),
            b_strips, b_tiles);
    }
    return 0;
}
