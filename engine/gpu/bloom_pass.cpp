#include "gpu/bloom_pass.hpp"

#include <algorithm>

#include "gpu/gl_check.hpp"
#include "gpu/pipeline.hpp"
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
    for (std::size_t i = 0; i < b.levels_.size(); ++i) {
        b.level_cells_[i] = TileSet(b.levels_[i].width, b.levels_[i].height, kLevelCell);
    }
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

PixelRect BloomPass::picture_reach(const LevelRegions& down, const PixelRect& from) const {
    // Up (shaders/bloom_up.frag), from the cut level to the top: each level adds its own
    // downsample; then shaders/finish.frag samples the top level at the pixel's centre,
    // bilinear.
    PixelRect level = from;
    for (std::size_t i = cut_level(); i-- > 0;) {
        const glm::dvec2 scale = glm::dvec2(size_of(i + 1)) / glm::dvec2(size_of(i));
        level = united(down[i], affected_by(level, scale, -1.0, 1.0, size_of(i)));
    }
    const glm::dvec2 scale = glm::dvec2(size_of(0)) / glm::dvec2(width_, height_);
    return affected_by(level, scale, 0.0, 0.0, {width_, height_});
}

bool BloomPass::mark_shown(const PixelRect& region, const GlareCut& cut) {
    if (region.empty()) return true;
    const std::size_t k = cut_level();
    read_back_.resize(static_cast<std::size_t>(region.area()) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, k + 1 == levels_.size()
                                               ? levels_[k].down_framebuffer.get()
                                               : levels_[k].sum_framebuffer.get());
    while (glGetError() != GL_NO_ERROR) {
    }
    glReadPixels(region.x0, region.y0, region.width(), region.height(), GL_RGBA, GL_FLOAT,
                 read_back_.data());
    if (glGetError() != GL_NO_ERROR) return false;
    // The sum holds levels() - k blurs, each the background's own colour where the content
    // does not reach; the finish mixes their sum in at share / levels().
    const glm::vec3 flat = cut.background * static_cast<float>(levels_.size() - k);
    const float weight = static_cast<float>(cut.share / static_cast<double>(levels_.size()));
    const float unseen = static_cast<float>(cut.unseen);
    const LevelRegions none{};
    for (int y = 0; y < region.height(); ++y) {
        const float* row = read_back_.data() + static_cast<std::size_t>(y) * region.width() * 4;
        const auto shown = [&](int i) {
            const glm::vec3 change =
                glm::abs(glm::vec3(row[i * 4], row[i * 4 + 1], row[i * 4 + 2]) - flat) * weight;
            return std::max({change.x, change.y, change.z}) >= unseen;
        };
        // Each run of shown texels along the row, marked as the pixels whose glare reads it.
        for (int x = 0; x < region.width();) {
            if (!shown(x)) {
                ++x;
                continue;
            }
            const int first = x;
            while (x < region.width() && shown(x)) ++x;
            shown_.mark(picture_reach(
                none, {region.x0 + first, region.y0 + y, region.x0 + x, region.y0 + y + 1}));
        }
    }
    return true;
}

void BloomPass::draw_over(std::vector<PixelRect>& rects, std::size_t level) {
    PixelRect about;
    long area = 0;
    for (const PixelRect& r : rects) {
        about = united(about, r);
        area += r.area();
    }
    if (area >= about.area()) {
        rects.assign(1, about);
    } else {
        // The tiles' rectangles, each widened by the filters' reach, overlap along their
        // shared edges: drawn as they are, those texels would be drawn twice. The cells of
        // kLevelCell texels they touch are drawn once each.
        TileSet& cells = level_cells_[level];
        cells.reset(levels_[level].width, levels_[level].height);
        for (const PixelRect& r : rects) cells.mark(r);
        cells.rects(rects);
    }
    rect_draw_.draw(rects, size_of(level));
}

void BloomPass::draw_sum(std::size_t i, std::vector<PixelRect>& rects) {
    const Level& smaller = levels_[i + 1];
    const Level& level = levels_[i];
    glBindFramebuffer(GL_FRAMEBUFFER, level.sum_framebuffer.get());
    glViewport(0, 0, level.width, level.height);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, level.down.get());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sum_texture(i + 1));
    up_.set("u_source_texel", glm::vec2(1.0f / static_cast<float>(smaller.width),
                                        1.0f / static_cast<float>(smaller.height)));
    up_.set("u_target_texel", glm::vec2(1.0f / static_cast<float>(level.width),
                                        1.0f / static_cast<float>(level.height)));
    draw_over(rects, i);
}

void BloomPass::follow_rects(const std::vector<PixelRect>& rects) {
    for (std::size_t i = 0; i < levels_.size(); ++i) {
        down_rects_[i].clear();
        sum_rects_[i].clear();
    }
    for (const PixelRect& r : rects) {
        LevelRegions down, sum;
        level_regions(r, down, sum);
        for (std::size_t i = 0; i < levels_.size(); ++i) {
            if (!down[i].empty()) down_rects_[i].push_back(down[i]);
            if (!sum[i].empty()) sum_rects_[i].push_back(sum[i]);
        }
    }
}

Result<const TileSet*> BloomPass::run(GLuint scene, const TileSet* content,
                                      const std::optional<GlareCut>& cut) {
    // Without a content (or a last one) the region is the whole picture: every level whole.
    damage_.rewrite(content, width_, height_).rects(tile_rects_);
    follow_rects(tile_rects_);
    glDisable(GL_SCISSOR_TEST);
    PipelineScope pass(Pipeline{&down_});
    glActiveTexture(GL_TEXTURE0);
    down_.set("u_source", 0);
    GLuint source = scene;
    glm::vec2 source_texel(1.0f / static_cast<float>(width_), 1.0f / static_cast<float>(height_));
    for (std::size_t i = 0; i < levels_.size(); ++i) {
        const Level& level = levels_[i];
        glBindFramebuffer(GL_FRAMEBUFFER, level.down_framebuffer.get());
        glViewport(0, 0, level.width, level.height);
        glBindTexture(GL_TEXTURE_2D, source);
        glBindSampler(0, i == 0 ? picture_sampler_.get() : 0);
        down_.set("u_source_texel", source_texel);
        down_.set("u_karis", i == 0 ? 1 : 0);
        draw_over(down_rects_[i], i);
        source = level.down.get();
        source_texel = glm::vec2(1.0f / static_cast<float>(level.width),
                                 1.0f / static_cast<float>(level.height));
    }
    glBindSampler(0, 0);
    // The smaller levels' sums where the content's glare reaches them, now or the last time:
    // elsewhere they hold the background's (the downsamples too, at every level).
    pass.change(Pipeline{&up_});
    up_.set("u_source", 0);
    up_.set("u_own", 1);
    const std::size_t k = cut_level();
    for (std::size_t i = levels_.size() - 1; i-- > k;) draw_sum(i, sum_rects_[i]);
    auto ok = gl_check("glare pass");
    if (!ok) return Error{ok.error()};
    if (content == nullptr) {
        shown_.reset(width_, height_, true);
        return &shown_;
    }
    // This frame's content and its glare: the finer levels' reach about each of its
    // rectangles, and the cut level's where the display shows it (all of it without a cut).
    shown_ = *content;
    content->rects(tile_rects_);
    // Marks each rectangle's reach through the finer levels, and through the cut level's sum
    // too where it is not read back; gives the cut level's texels the rectangles reach.
    const auto mark_reach = [&](bool cut_level_too) {
        PixelRect read;
        for (const PixelRect& r : tile_rects_) {
            LevelRegions down, sum;
            level_regions(r, down, sum);
            shown_.mark(picture_reach(down, cut_level_too ? sum[k] : PixelRect{}));
            read = united(read, sum[k]);
        }
        return read;
    };
    const bool cutting = cut && !cut_unavailable_;
    const PixelRect read = mark_reach(!cutting);
    if (cutting && !mark_shown(read, *cut)) {
        cut_unavailable_ = true;
        mark_reach(true);
    }
    return &shown_;
}

Result<bool> BloomPass::spread(const TileSet& region) {
    // The wider levels' sums are this frame's only where the picture's `region` reads them,
    // through the finish's bilinear tap and each step up's ±1 texels: they are drawn there and
    // nowhere else, so what they hold elsewhere (an earlier frame's glare) is never read.
    const std::size_t k = cut_level();
    if (k == 0 || region.empty()) return true;
    region.rects(tile_rects_);
    for (std::size_t i = 0; i < k; ++i) sum_rects_[i].clear();
    for (const PixelRect& r : tile_rects_) {
        PixelRect needed =
            read_by(r, glm::dvec2(size_of(0)) / glm::dvec2(width_, height_), 0.0, 0.0, size_of(0));
        for (std::size_t i = 0; i < k && !needed.empty(); ++i) {
            if (i > 0) {
                needed = read_by(needed, glm::dvec2(size_of(i)) / glm::dvec2(size_of(i - 1)), -1.0,
                                 1.0, size_of(i));
            }
            sum_rects_[i].push_back(needed);
        }
    }
    glDisable(GL_SCISSOR_TEST);
    const PipelineScope pass(Pipeline{&up_});
    up_.set("u_source", 0);
    up_.set("u_own", 1);
    for (std::size_t i = k; i-- > 0;) draw_sum(i, sum_rects_[i]);
    return gl_check("glare: spread");
}

}  // namespace gem::gpu
