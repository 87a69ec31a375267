#include "gpu/bloom_pass.hpp"

#include <algorithm>

#include "gpu/gl_check.hpp"
#include "gpu/program_catalog.hpp"

namespace gem::gpu {

namespace {

constexpr int kMinSide = 8;

}  // namespace

Result<BloomPass> BloomPass::make(int width, int height) {
    auto down = build_program("bloom_down");
    if (!down) return Error{down.error()};
    auto up = build_program("bloom_up");
    if (!up) return Error{up.error()};
    BloomPass b(std::move(down).value(), std::move(up).value());
    b.empty_ = make_vertex_array();
    b.picture_sampler_ = make_sampler(GL_LINEAR);
    b.width_ = width;
    b.height_ = height;
    int w = width / 2, h = height / 2;
    while (static_cast<int>(b.levels_.size()) < kMaxLevels && std::min(w, h) >= kMinSide) {
        Level level;
        level.width = w;
        level.height = h;
        level.down = make_texture_2d(GL_RGBA16F, w, h, GL_LINEAR);
        level.down_framebuffer = make_framebuffer_with(level.down.get());
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            return Error{"glare: the GPU cannot render to RGBA16F"};
        }
        b.levels_.push_back(std::move(level));
        w /= 2;
        h /= 2;
    }
    if (b.levels_.empty()) return Error{"glare: the picture is too small for a glare pyramid"};
    for (std::size_t i = 0; i + 1 < b.levels_.size(); ++i) {
        Level& level = b.levels_[i];
        level.sum = make_texture_2d(GL_RGBA16F, level.width, level.height, GL_LINEAR);
        level.sum_framebuffer = make_framebuffer_with(level.sum.get());
    }
    auto ok = gl_check("glare: allocate");
    if (!ok) return Error{ok.error()};
    return b;
}

GLuint BloomPass::glare_texture() const {
    return sum_texture(0);
}

void BloomPass::level_regions(const PixelRect& region, LevelRegions& down,
                              LevelRegions& sum) const {
    // Down (shaders/bloom_down.frag): texel j of a level samples its source at (j + 0.5) · 2
    // source texels, taps ±2 texels about it, bilinear.
    PixelRect source = region;
    for (std::size_t i = 0; i < levels_.size(); ++i) {
        down[i] = affected_by(source, glm::dvec2(2.0), -2.0, 2.0, size_of(i));
        source = down[i];
    }
    // Up (shaders/bloom_up.frag): texel j samples the smaller level's sum at (j + 0.5) · its
    // size / this level's size, taps ±1 of its texels, bilinear; and its own downsample.
    sum[levels_.size() - 1] = down[levels_.size() - 1];
    for (std::size_t i = levels_.size() - 1; i-- > 0;) {
        const glm::dvec2 scale = glm::dvec2(size_of(i + 1)) / glm::dvec2(size_of(i));
        sum[i] = united(down[i], affected_by(sum[i + 1], scale, -1.0, 1.0, size_of(i)));
    }
}

PixelRect BloomPass::reach(const PixelRect& content) const {
    LevelRegions down, sum;
    level_regions(content, down, sum);
    // shaders/finish.frag samples the top level at the pixel's centre, bilinear.
    const glm::dvec2 scale = glm::dvec2(size_of(0)) / glm::dvec2(width_, height_);
    return united(content, affected_by(sum[0], scale, 0.0, 0.0, {width_, height_}));
}

Result<bool> BloomPass::run(GLuint scene, const std::optional<PixelRect>& content) {
    // Without a content (or a last one) the region is the whole picture: every level whole.
    LevelRegions down, sum;
    level_regions(damage_.rewrite(content, PixelRect::whole(width_, height_)), down, sum);
    const auto scissor = [](const PixelRect& r) { glScissor(r.x0, r.y0, r.width(), r.height()); };
    glEnable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(empty_.get());
    glActiveTexture(GL_TEXTURE0);
    down_.use();
    down_.set("u_source", 0);
    GLuint source = scene;
    glm::vec2 source_texel(1.0f / static_cast<float>(width_), 1.0f / static_cast<float>(height_));
    for (std::size_t i = 0; i < levels_.size(); ++i) {
        const Level& level = levels_[i];
        glBindFramebuffer(GL_FRAMEBUFFER, level.down_framebuffer.get());
        glViewport(0, 0, level.width, level.height);
        scissor(down[i]);
        glBindTexture(GL_TEXTURE_2D, source);
        glBindSampler(0, i == 0 ? picture_sampler_.get() : 0);
        down_.set("u_source_texel", source_texel);
        down_.set("u_karis", i == 0 ? 1 : 0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        source = level.down.get();
        source_texel = glm::vec2(1.0f / static_cast<float>(level.width),
                                 1.0f / static_cast<float>(level.height));
    }
    glBindSampler(0, 0);
    up_.use();
    up_.set("u_source", 0);
    up_.set("u_own", 1);
    for (std::size_t i = levels_.size() - 1; i-- > 0;) {
        const Level& smaller = levels_[i + 1];
        const Level& level = levels_[i];
        glBindFramebuffer(GL_FRAMEBUFFER, level.sum_framebuffer.get());
        glViewport(0, 0, level.width, level.height);
        scissor(sum[i]);
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, level.down.get());
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, sum_texture(i + 1));
        up_.set("u_source_texel", glm::vec2(1.0f / static_cast<float>(smaller.width),
                                            1.0f / static_cast<float>(smaller.height)));
        up_.set("u_target_texel", glm::vec2(1.0f / static_cast<float>(level.width),
                                            1.0f / static_cast<float>(level.height)));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    return gl_check("glare pass");
}

}  // namespace gem::gpu
