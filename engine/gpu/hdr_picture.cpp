#include "gpu/hdr_picture.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <GLES3/gl31.h>

#include "gpu/gl_check.hpp"
#include "gpu/gl_extensions.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/program_catalog.hpp"
#include "util/elapsed.hpp"
#include "util/radical_inverse.hpp"

namespace gem::gpu {

namespace {

// Samples the GPU offers for `format` as a renderbuffer (its largest, 0 when none).
int max_samples(GLenum format) {
    GLint count = 0;
    glGetInternalformativ(GL_RENDERBUFFER, format, GL_NUM_SAMPLE_COUNTS, 1, &count);
    if (count <= 0) return 0;
    GLint largest = 0;
    glGetInternalformativ(GL_RENDERBUFFER, format, GL_SAMPLES, 1, &largest);  // descending
    return largest;
}

bool complete() {
    return glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

}  // namespace

Result<HdrPicture> HdrPicture::make(int width, int height, const PictureOptions& options) {
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (width < 1 || height < 1 || width > max_size || height > max_size) {
        return Error{"picture: " + std::to_string(width) + "×" + std::to_string(height) +
                     " is outside 1.." + std::to_string(max_size)};
    }
    auto finish = build_program("finish");
    if (!finish) return Error{finish.error()};
    HdrPicture p(std::move(finish).value());
    p.options_ = options;
    p.schedule_ = StillSchedule({.frames = options.still_frames,
                                 .depth = options.still_depth,
                                 .depth_max = options.still_depth_max,
                                 .seconds = options.still_seconds,
                                 .frame_ms = options.still_frame_ms});
    p.width_ = width;
    p.height_ = height;
    while (glGetError() != GL_NO_ERROR) {
    }

    // The resolved (or only) scene picture: RGBA16F where renderable, else 8-bit sRGB.
    for (const GLenum format : {GLenum(GL_RGBA16F), GLenum(GL_SRGB8_ALPHA8)}) {
        p.resolved_ = make_texture_2d(format, width, height, GL_NEAREST);
        p.resolved_depth_ = make_depth_renderbuffer(width, height);
        p.resolved_framebuffer_ = make_framebuffer_with(p.resolved_.get(), p.resolved_depth_.get());
        p.high_range_ = format == GL_RGBA16F;
        if (glGetError() == GL_NO_ERROR && complete()) break;
        p.resolved_framebuffer_.reset();
    }
    if (!p.resolved_framebuffer_) return Error{"picture: no renderable colour format"};
    const GLenum colour_format = p.high_range_ ? GLenum(GL_RGBA16F) : GLenum(GL_SRGB8_ALPHA8);

    const int samples =
        std::min({options.samples, max_samples(colour_format), max_samples(GL_DEPTH24_STENCIL8)});
    if (samples > 1) {
        p.multisampled_depth_ = make_depth_renderbuffer(width, height, samples);
        p.multisampled_ = make_framebuffer();
        glBindFramebuffer(GL_FRAMEBUFFER, p.multisampled_.get());
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  p.multisampled_depth_.get());
        // Where the GL has multisampled textures (ES 3.1), the scene's samples are one and a
        // shader resolves them over the tiles a frame rewrites; else a renderbuffer, resolved by
        // one blit about those tiles.
        if (p.high_range_ && gl_version_at_least(3, 1)) {
            auto resolve = build_program("resolve", {}, "310 es");
            if (resolve) {
                p.multisampled_samples_ = make_texture();
                glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, p.multisampled_samples_.get());
                // Fixed sample locations: the depth attachment is a renderbuffer.
                glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, colour_format, width,
                                          height, GL_TRUE);
                glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
                glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                       GL_TEXTURE_2D_MULTISAMPLE, p.multisampled_samples_.get(), 0);
                if (glGetError() == GL_NO_ERROR && complete()) {
                    p.resolve_.emplace(std::move(resolve).value());
                } else {
                    p.multisampled_samples_.reset();
                }
            }
        }
        if (!p.resolve_) {
            p.multisampled_colour_ = make_renderbuffer();
            glBindRenderbuffer(GL_RENDERBUFFER, p.multisampled_colour_.get());
            glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, colour_format, width,
                                             height);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                      p.multisampled_colour_.get());
        }
        if (glGetError() == GL_NO_ERROR && complete()) {
            // A complete framebuffer's attachments have one sample count: the depth's.
            glBindRenderbuffer(GL_RENDERBUFFER, p.multisampled_depth_.get());
            glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &p.samples_);
            p.samples_ = std::max(p.samples_, 1);
        } else {
            p.multisampled_.reset();
            p.resolve_.reset();
        }
    }

    if (p.high_range_ && options.still_frames > 1) {
        auto accumulate = build_program("accumulate");
        if (!accumulate) return Error{accumulate.error()};
        p.accumulate_.emplace(std::move(accumulate).value());
        // Half floats hold a mean of a few dozen frames: frame k moves it by 1 / (k + 1) of
        // its difference, which falls under a float16 step (an 11-bit significand) for ever
        // more pixels as k grows, and each rounding drifts it. A pixel flickering as fire does
        // ends 10 sRGB steps dark after 1024 frames (GpuPicture.AStillViewOfManyFramesIsTheirMean).
        // On a diamond at depth 64 (bench_still_picture --still-frames N, the wavelengths then
        // in base-2 order): 64 frames ΔE00 3.11 in half floats, 3.06 in floats; 1024 frames
        // 4.39 against 3.08. So beyond 64 frames the mean is kept in floats where the GPU
        // renders and blends them, and filters them where the glare reads the mean; at the
        // kiosk's 16 the half floats' bandwidth is enough (ΔE00 0.02 apart).
        p.mean_high_precision_ =
            options.still_frames > kHalfFloatMeanFrames &&
            gl_has_extension("GL_EXT_color_buffer_float") &&
            gl_has_extension("GL_EXT_float_blend") &&
            (options.glare <= 0.0 || gl_has_extension("GL_OES_texture_float_linear"));
        // Checked here on one texel; the picture-sized mean is made at the first still frame:
        // on llvmpipe a new texture's pages are filled as it is made (0.13 s for 1080p in
        // RGBA32F), time the first frame on screen need not wait for.
        const Texture probe = make_texture_2d(p.mean_format(), 1, 1, GL_NEAREST);
        const Framebuffer probe_framebuffer = make_framebuffer_with(probe.get());
        if (!complete()) return Error{"picture: the still view's mean cannot be rendered"};
        if (options.spectral) {
            p.spectrum_.emplace(options.still_frames);
        }
    }
    if (p.high_range_ && options.glare > 0.0) {
        auto glare = BloomPass::make(width, height);
        if (!glare) return Error{glare.error()};
        p.glare_.emplace(std::move(glare).value());
    }
    auto ok = gl_check("picture: allocate");
    if (!ok) return Error{ok.error()};
    return p;
}

void HdrPicture::begin_frame(bool still, double now_s) {
    // The next band of a still frame drawn in bands; a touch ends it at once.
    if (still && band_ + 1 < bands_.bands() && accumulating()) {
        ++band_;
        return;
    }
    band_ = 0;
    still_and_whole_ = still && drawn_whole_;
    schedule_.begin_frame(still && accumulate_.has_value(), now_s);
    bands_.start(accumulating() ? schedule_.bands() : 1);
}

void HdrPicture::frame_drawn(double ms, bool stand_in) {
    drawn_whole_ = !stand_in;
    bands_.measured(band_, ms);
    // A frame in bands is judged by its dearest band, what a touch waits for.
    if (band_ + 1 >= bands_.bands()) schedule_.frame_drawn(bands_.dearest_ms() * bands_.bands());
}

std::optional<PixelRect> HdrPicture::band() const {
    if (!accumulating() || bands_.bands() <= 1) return std::nullopt;
    // Rows of what the scene covers (all of it without a cover).
    return bands_.rows(cover_ ? cover_->tiles.bounds() : PixelRect::whole(width_, height_), band_);
}

bool HdrPicture::accumulating() const {
    return schedule_.index() >= 0 && !schedule_.settled();
}

StillFrame HdrPicture::still_frame() const {
    StillFrame still;
    if (!accumulating()) return still;
    if (spectrum_) still.wavelengths = &spectrum_->frame(schedule_.index());
    still.depth = schedule_.depth();
    still.index = schedule_.index();
    return still;
}

bool HdrPicture::settled() const {
    return accumulate_ ? schedule_.settled() : still_and_whole_;
}

int HdrPicture::still_frames_drawn() const {
    return schedule_.index() + 1;
}

glm::dvec2 HdrPicture::jitter_ndc() const {
    // The first frame of a still view is the moving view's own (no offset): the picture does
    // not jump when a turn stops. Then Halton (2, 3), centred on the pixel.
    if (schedule_.index() <= 0) return glm::dvec2(0.0);
    const auto i = static_cast<unsigned>(schedule_.index());
    const glm::dvec2 offset_px(radical_inverse(i, 2) - 0.5, radical_inverse(i, 3) - 0.5);
    return offset_px * glm::dvec2(2.0 / width_, 2.0 / height_);
}

bool HdrPicture::multisampled_frame() const {
    return multisampled_ && schedule_.index() <= 0;
}

void HdrPicture::forget_all() {
    resolved_damage_.forget();
    mean_damage_.forget();
    target_damage_.forget();
    if (glare_) glare_->forget();
}

namespace {

void scissor(const PixelRect& r) {
    glScissor(r.x0, r.y0, r.width(), r.height());
}

}  // namespace

const TileSet* HdrPicture::content() const {
    return cover_ ? &cover_->tiles : nullptr;
}

void HdrPicture::bind(const SceneCover* cover) {
    // A cover of another picture's size says nothing of this one's.
    if (cover != nullptr && (cover->tiles.width() != width_ || cover->tiles.height() != height_)) {
        cover = nullptr;
    }
    if (cover == nullptr || !cover_ || cover_->background != cover->background) forget_all();
    if (cover != nullptr) {
        cover_ = *cover;
    } else {
        cover_.reset();
    }
    // The scene is drawn whole, cleared first: a clear of the whole framebuffer is the cheap
    // one (a tiled GPU need not load its tiles; llvmpipe clears tiles without rasterising:
    // bench_picture measured a scissored clear of the 4× MSAA picture at 1080p 7 ms dearer),
    // and the scene's own draws cover only their pixels. A still frame after the first draws
    // straight into the resolved picture, whose content is then this frame's.
    if (!multisampled_frame()) resolved_damage_.rewrite(content(), width_, height_);
    glBindFramebuffer(GL_FRAMEBUFFER,
                      multisampled_frame() ? multisampled_.get() : resolved_framebuffer_.get());
    glViewport(0, 0, width_, height_);
    // A still frame drawn in bands draws this band's rows only, its clear included.
    if (const std::optional<PixelRect> rows = band()) {
        glEnable(GL_SCISSOR_TEST);
        scissor(*rows);
    } else {
        glDisable(GL_SCISSOR_TEST);
    }
}

Result<bool> HdrPicture::finish(const RenderTarget& picture, FinishTimes* times) {
    auto t0 = std::chrono::steady_clock::now();
    const auto lap = [&](double* into) {
        if (times == nullptr) return;
        glFinish();
        *into = ms_since(t0);
        t0 = std::chrono::steady_clock::now();
    };
    if (times != nullptr) glFinish();
    t0 = std::chrono::steady_clock::now();
    const glm::ivec2 size(width_, height_);
    glDisable(GL_SCISSOR_TEST);
    if (multisampled_frame()) {
        const TileSet& rewritten = resolved_damage_.rewrite(content(), width_, height_);
        if (resolve_) {
            glBindFramebuffer(GL_FRAMEBUFFER, resolved_framebuffer_.get());
            glViewport(0, 0, width_, height_);
            const PipelineScope pass(Pipeline{&*resolve_});
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, multisampled_samples_.get());
            resolve_->set("u_samples", 0);
            resolve_->set("u_sample_count", samples_);
            rewritten.rects(rects_);
            rect_draw_.draw(rects_, size);
            glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
        } else {
            // One blit about the tiles: a blit each costs llvmpipe ~0.1 ms (bench_pass_floor).
            const PixelRect r = rewritten.bounds();
            glEnable(GL_SCISSOR_TEST);  // the blit is scissored
            scissor(r);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_.get());
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_framebuffer_.get());
            glBlitFramebuffer(r.x0, r.y0, r.x1, r.y1, r.x0, r.y0, r.x1, r.y1, GL_COLOR_BUFFER_BIT,
                              GL_NEAREST);
            glDisable(GL_SCISSOR_TEST);
        }
    }
    GLuint scene = resolved_.get();
    if (accumulating()) {
        // The running mean: the k-th frame (from 0) has weight 1 / (k + 1).
        if (!mean_framebuffer_) {
            mean_ = make_texture_2d(mean_format(), width_, height_, GL_NEAREST);
            mean_framebuffer_ = make_framebuffer_with(mean_.get());
            if (!complete()) return Error{"picture: the still view's mean cannot be rendered"};
            mean_damage_.forget();
        }
        glBindFramebuffer(GL_FRAMEBUFFER, mean_framebuffer_.get());
        glViewport(0, 0, width_, height_);
        // A band adds its rows only: each row has then had each frame of the view once. The
        // tiles' rectangles are disjoint: each pixel is blended once.
        mean_damage_.rewrite(content(), width_, height_).rects(rects_);
        if (const std::optional<PixelRect> rows = band()) {
            for (PixelRect& r : rects_) r = intersected(r, *rows);
        }
        const PipelineScope pass(Pipeline{&*accumulate_, Blend::constant_alpha});
        glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / static_cast<float>(schedule_.index() + 1));
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, resolved_.get());
        accumulate_->set("u_scene", 0);
        rect_draw_.draw(rects_, size);
    }
    if (schedule_.index() >= 0) scene = mean_.get();
    lap(times ? &times->resolve_ms : nullptr);
    // A band before its frame's last: the picture shown changes once the frame is whole, so
    // its glare and tone curve wait for that (they would cost every band what a frame costs).
    if (band() && band_ + 1 < bands_.bands()) {
        target_region_.reset(width_, height_);
        return true;
    }
    const bool glare = glare_ && options_.glare > 0.0;
    // What the finish rewrites: the piece's tiles and those its glare reaches (cut where the
    // display shows none of it), and what it rewrote the last time.
    const TileSet* shown = content();
    if (glare) {
        auto ran = glare_->run(scene, content(), glare_cut());
        if (!ran) return Error{ran.error()};
        if (shown != nullptr) shown = ran.value();
    }
    if (picture.framebuffer() != last_target_) target_damage_.forget();
    last_target_ = picture.framebuffer();
    target_region_ = target_damage_.rewrite(shown, width_, height_);
    if (glare) {
        auto spread = glare_->spread(target_region_);
        if (!spread) return spread;
    }
    lap(times ? &times->glare_ms : nullptr);

    picture.bind();
    const PipelineScope pass(Pipeline{&finish_});
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, scene);
    finish_.set("u_scene", 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, glare ? glare_->glare_texture() : scene);
    finish_.set("u_glare", 1);
    finish_.set("u_glare_share", glare ? static_cast<float>(options_.glare) : 0.0f);
    finish_.set("u_glare_levels", glare ? static_cast<float>(glare_->levels()) : 1.0f);
    finish_.set("u_exposure", static_cast<float>(std::exp2(options_.display.exposure_ev)));
    finish_.set("u_tone_curve", options_.display.curve == ToneCurve::clip ? 0 : 1);
    target_region_.rects(rects_);
    rect_draw_.draw(rects_, size);
    glActiveTexture(GL_TEXTURE0);
    lap(times ? &times->tone_ms : nullptr);
    return gl_check("picture: finish");
}

std::optional<GlareCut> HdrPicture::glare_cut() {
    if (!cover_ || !options_.glare_cut) return std::nullopt;
    const glm::dvec3 background(cover_->background);
    // The mixed picture is the background itself where the glare adds nothing.
    if (!unseen_ || unseen_->background != background ||
        unseen_->display.curve != options_.display.curve ||
        unseen_->display.exposure_ev != options_.display.exposure_ev) {
        unseen_ =
            UnseenChange{background, options_.display, unseen_change(background, options_.display)};
    }
    return GlareCut{cover_->background, options_.glare, unseen_->change};
}

std::string HdrPicture::describe() const {
    std::string mean;
    if (accumulate_ && options_.still_frames > kHalfFloatMeanFrames) {
        mean = mean_high_precision_ ? " (mean in RGBA32F)"
                                    : " (mean in RGBA16F, no float blending: it rounds past " +
                                          std::to_string(kHalfFloatMeanFrames) + " frames)";
    }
    std::string depth;
    if (accumulate_ && options_.still_depth > 0) {
        depth = ", traced to depth " + std::to_string(options_.still_depth);
        if (options_.still_depth_max > options_.still_depth) {
            depth += " and deeper to " + std::to_string(options_.still_depth_max);
        }
    }
    if (accumulate_ && options_.still_seconds > 0.0) {
        depth += ", for at most " + std::to_string(options_.still_seconds).substr(0, 4) + " s";
    }
    char line[400];
    std::snprintf(
        line, sizeof line, "%s, %d× MSAA, %s%d frames a still view%s%s%s, %s, %s at %+.1f EV",
        high_range_ ? "RGBA16F" : "8-bit sRGB (no float target: highlights clip)", samples_,
        accumulate_ && options_.still_seconds > 0.0 ? "up to " : "",
        accumulate_ ? options_.still_frames : 1, mean.c_str(),
        spectrum_ ? ", each its own wavelengths" : "", depth.c_str(),
        glare_ && options_.glare > 0.0
            ? ("glare " + std::to_string(options_.glare).substr(0, 4) + " over " +
               std::to_string(glare_->levels()) + " levels" +
               (!options_.glare_cut         ? ", uncut"
                : glare_->cut_unavailable() ? ", uncut (the GL reads no float texels back)"
                                            : ", cut where unseen"))
                  .c_str()
            : "no glare",
        to_string(options_.display.curve), options_.display.exposure_ev);
    return line;
}

}  // namespace gem::gpu
