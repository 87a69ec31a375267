#pragma once
// The picture as the scene is drawn into it, before the display: linear radiance in RGBA16F
// (highlights above 1 kept), multisampled, with a depth buffer. finish() resolves the
// samples, spreads the glare (bloom_pass.hpp) and applies the exposure and tone curve
// (picture/tone_map.hpp) into a display picture (render_target.hpp), which the kiosk presents
// and snapshots and gemrender writes.
//
// Where the GPU cannot render RGBA16F (ES 3.0 without EXT_color_buffer_half_float) the scene
// goes into 8-bit sRGB instead: highlights clip before the tone curve and there is no glare;
// where it cannot multisample RGBA16F, it draws one sample. describe() says which.
//
// A still view gets better with every frame: the frames drawn while the view stays still are
// averaged, each with the camera moved by a different sub-pixel offset (jitter_ndc(), the
// Halton (2, 3) sequence), so edges inside the stone, where the rays' paths through it change,
// are sampled several times a pixel as the CPU reference samples them; after its first they
// are drawn without MSAA (point samples, multisampled_frame()). Any motion restarts the mean;
// after `still_frames` frames, or `still_seconds`, more drawing changes nothing (settled()).
// Without a mean (still_frames 1), a still view is settled once it has been drawn whole, no
// stand-in among its views (FrameStats::stand_in): the picture on screen is all it gets.
//
// With spectral fire (PictureOptions::spectral) each still frame also traces its own
// wavelengths, one per colour channel (still_frame(), optics/spectrum.hpp: StillSpectrum), so
// that the mean of a still view's frames is each channel's spectral integral; and they may
// trace deeper than the moving frames (still_depth), deeper still as they accumulate, for as
// long as the view is given (still_schedule.hpp). A still frame that would keep a touch
// waiting longer than still_frame_ms is drawn in horizontal bands, one a frame (band()); each
// band adds its rows to the mean with the frame's weight, so the mean is every row's own, and
// the picture shown is finished once the frame is whole.
//
// Where the scene is a piece on one flat colour (a SceneCover given to bind()), every pass after
// the scene runs only where the picture changes: over the tiles the piece covers in this frame
// and those it covered the last time each surface was drawn (tile_set.hpp, TileDamage), and
// those its glare reaches where the display shows it. Outside, each surface still holds the
// background as a whole frame left it; a new background colour, a new display transform or
// another target rewrites them whole.

#include <optional>

#include <glm/vec2.hpp>
#include <string>

#include "gpu/bloom_pass.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/pixel_rect.hpp"
#include "gpu/program.hpp"
#include "gpu/rect_draw.hpp"
#include "gpu/render_target.hpp"
#include "gpu/scene_cover.hpp"
#include "gpu/still_bands.hpp"
#include "gpu/still_schedule.hpp"
#include "optics/spectrum.hpp"
#include "picture/tone_map.hpp"
#include "util/result.hpp"

namespace gem::gpu {

struct PictureOptions {
    int samples = 4;           // MSAA samples asked for; fewer where the GPU has fewer
    DisplayTransform display;  // exposure and tone curve
    double glare = 0.04;       // share of the picture spread into glare; 0: none
    // Around a piece on a flat background, the glare ends where it changes no pixel of the
    // 8-bit picture by half a step (GlareCut); false: wherever its filters reach.
    bool glare_cut = true;
    int still_frames = 16;  // frames averaged while the view is still; 1: none
    // Spectral fire: each still frame traces its own wavelengths, one per channel
    // (still_frame()); needs still_frames > 1.
    bool spectral = false;
    // The depth the trace follows in a still view's frames where deeper than the moving
    // frames' (0: theirs). The
    // still view's cost is latency, not frame rate (it stops once settled), and the light a
    // ray still carries when its depth runs out has no cheaper stand-in (docs/accuracy.md).
    int still_depth = 0;
    // The depth still frames come to as they accumulate (StillSchedule: doubled each time the
    // frames double); at most still_depth: never deeper than it.
    int still_depth_max = 0;
    // How long a still view is refined after it stopped (0: until its still_frames), and how
    // long a deeper still frame may keep a touch waiting (0: any): StillScheduleOptions.
    double still_seconds = 0.0;
    double still_frame_ms = 0.0;
};

// Each pass's time, measured with glFinish between passes (only when asked: it stalls).
struct FinishTimes {
    double resolve_ms = 0.0;
    double glare_ms = 0.0;
    double tone_ms = 0.0;
};

class HdrPicture {
  public:
    // Errors: a size outside the GPU's limits, no renderable colour format at all.
    static Result<HdrPicture> make(int width, int height, const PictureOptions& options);

    // Before drawing each frame: `still` says its view is the last frame's, `now_s` when it
    // begins (a still view's time is counted from its first frame; any clock). The camera of
    // the frame should be moved by jitter_ndc() (CameraSettings::shift).
    void begin_frame(bool still, double now_s = 0.0);
    // After drawing it: what it cost (ms), by which a still view's next frame is judged, and
    // whether it showed a stand-in for a view not yet resident (FrameStats::stand_in).
    void frame_drawn(double ms, bool stand_in = false);
    glm::dvec2 jitter_ndc() const;
    // What this frame traces differently (FrameRenderer::render): a still frame's wavelengths,
    // when the picture is spectral, and its depth; a moving frame's defaults else.
    StillFrame still_frame() const;
    // The still view has its frames, or its time, or (without a mean) a whole frame: drawing it
    // again changes nothing.
    bool settled() const;
    // The frames the still view's mean holds once this frame is drawn (0 while moving).
    int still_frames_drawn() const;
    // How this still view was refined: its time, its depths.
    const StillSchedule& still_schedule() const { return schedule_; }
    // A still view's frames are averaged (still_frames > 1).
    bool averages() const { return accumulate_.has_value(); }
    // The picture is as good as this view gets: settled, or no averaging at all.
    bool refined() const { return !averages() || settled(); }
    // Binds the scene framebuffer as the draw framebuffer, viewport = the whole picture, for
    // a frame whose scene covers `cover` (FrameRenderer::cover(); null: anything). The scene
    // is drawn whole (its clear is cheapest so); finish() runs over the cover's tiles.
    void bind(const SceneCover* cover = nullptr);
    // The scene into `picture` (the same size), rewriting only where it changes (bind()'s
    // cover); the scissor test is off after it. `times`: measure each pass (stalls the GPU).
    Result<bool> finish(const RenderTarget& picture, FinishTimes* times = nullptr);
    // The target's tiles the last finish() wrote: what a display must show anew.
    const TileSet& target_region() const { return target_region_; }
    // The target was drawn over outside finish() (a cross-fade): the next one rewrites it whole.
    void forget_target() { target_damage_.forget(); }

    void set_display(const DisplayTransform& display) {
        options_.display = display;
        target_damage_.forget();
    }
    const PictureOptions& options() const { return options_; }
    int samples() const { return samples_; }
    bool high_range() const { return high_range_; }
    int width() const { return width_; }
    int height() const { return height_; }
    // "RGBA16F, 4× MSAA, glare 0.04 over 6 levels, neutral at +0.0 EV".
    std::string describe() const;

  private:
    explicit HdrPicture(Program finish) : finish_(std::move(finish)) {}
    // This frame is drawn multisampled: a moving frame, or a still view's first (the moving
    // view's own, shown as the turn stops). The still frames after it are single samples at
    // their sub-pixel offsets: MSAA shades a pixel's samples on a facet at the pixel's centre,
    // so where a facet edge crosses the pixel its coverage weights a path the centre ray takes
    // through a neighbouring facet's plane. The mean of point samples has no such bias: a
    // diamond's still picture of 256 frames at depth 64 comes ΔE00 0.63 from the D-line
    // reference without MSAA, 0.93 with it (1.57 and 1.94 with spectral fire), and each frame
    // costs less (bench_still_picture --msaa).
    bool multisampled_frame() const;
    // This frame is added to the still view's mean.
    bool accumulating() const;
    // The rows this frame draws and adds to the mean, when its still frame is drawn in bands
    // (StillSchedule::bands(): one band a frame, so a touch waits for one band only).
    std::optional<PixelRect> band() const;
    // Every surface rewritten whole at its next frame.
    void forget_all();
    // Where this frame's glare may be cut (nullopt: no flat background, or no cut asked for).
    std::optional<GlareCut> glare_cut();
    // The tiles the scene covers (null: anywhere).
    const TileSet* content() const;

    PictureOptions options_;
    int width_ = 0;
    int height_ = 0;
    int samples_ = 1;
    bool high_range_ = true;
    // Multisampled: the scene's samples, resolved into resolved_; else drawn there. Its colour
    // is a multisampled texture resolved by resolve_ where the GL has them, else a renderbuffer.
    Framebuffer multisampled_;
    Texture multisampled_samples_;
    std::optional<Program> resolve_;
    Renderbuffer multisampled_colour_;
    Renderbuffer multisampled_depth_;
    Framebuffer resolved_framebuffer_;
    Texture resolved_;
    Renderbuffer resolved_depth_;
    // The still view's running mean: RGBA16F, or RGBA32F (mean_high_precision_) for more than
    // kHalfFloatMeanFrames frames where the GPU can blend floats (and filter them, for the
    // glare).
    static constexpr int kHalfFloatMeanFrames = 64;
    Texture mean_;  // made at the first still frame
    bool mean_high_precision_ = false;
    GLenum mean_format() const { return mean_high_precision_ ? GL_RGBA32F : GL_RGBA16F; }
    Framebuffer mean_framebuffer_;
    StillSchedule schedule_;        // this frame's place in the still view's mean, and its depth
    int band_ = 0;                  // the band of its still frame this frame draws
    bool drawn_whole_ = false;      // without a mean: the last frame drawn showed no stand-in
    bool still_and_whole_ = false;  // ... and this frame's view is that one's (settled())
    StillBands bands_;              // where that still frame's bands lie, and what they cost
    std::optional<StillSpectrum> spectrum_;
    std::optional<Program> accumulate_;
    std::optional<BloomPass> glare_;
    Program finish_;
    RectDraw rect_draw_;
    std::vector<PixelRect> rects_;  // a pass's rectangles, kept between frames
    // This frame's cover (the last frame's until bind()), and where each surface differs from
    // the background.
    std::optional<SceneCover> cover_;
    TileDamage resolved_damage_;
    TileDamage mean_damage_;
    TileDamage target_damage_;
    GLuint last_target_ = 0;
    TileSet target_region_;
    // unseen_change() of the background under the display transform it was found for.
    struct UnseenChange {
        glm::dvec3 background;
        DisplayTransform display;
        double change = 0.0;
    };
    std::optional<UnseenChange> unseen_;
};

}  // namespace gem::gpu
