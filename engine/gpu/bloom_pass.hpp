#pragma once
// The glare around bright exits: a pyramid of half-size RGBA16F levels (Jimenez 2014, see
// shaders/bloom_down.frag), filtered down from the HDR picture and added back up. The top
// level then holds the sum of `levels()` ever wider blurs of the picture, each with the
// picture's energy; shaders/finish.frag mixes their mean in.
//
// Each level keeps its downsample and its sum apart (the sum is the downsample plus the wider
// level's sum, upsampled: shaders/bloom_up.frag), so that where a piece on a flat background
// changes only some tiles of the picture, a level's downsample is redrawn only where those
// tiles reach it, and its sum only where the sums below reach it (TileDamage, tile_set.hpp):
// each of the tiles' rectangles (TileSet::rects()) is followed through the levels, and a
// level drawn over the rectangles it reaches, in one draw (rect_draw.hpp).
//
// The glare of a piece on a flat background fades over its filters' reach (a tenth of the
// picture's height each side at 1080p), far past where it still shows: at the kiosk's start
// view, 8-bit codes stop changing a few pixels from the ring. So the sum of a level of 8-pixel
// texels is read back, and the picture finished only where that sum, mixed in, changes the
// picture by as much as the display shows (GlareCut), tile by tile; the wider levels' sums are
// spread only where those tiles read them (spread()). Beyond, the glare moves no code by half a
// step.

#include <array>
#include <optional>
#include <vector>

#include "gpu/gl_handles.hpp"
#include "gpu/pixel_rect.hpp"
#include "gpu/program.hpp"
#include "gpu/rect_draw.hpp"
#include "gpu/tile_set.hpp"
#include "util/result.hpp"

namespace gem::gpu {

// Where the glare is cut: around a piece on a flat `background`, beyond the pixels where the
// glare, mixed in at `share`, moves the picture's radiance by `unseen` (picture/tone_map.hpp:
// unseen_change()) or more in some channel: there it moves no 8-bit code by half a step.
struct GlareCut {
    glm::vec3 background{0.0f};
    double share = 0.0;
    double unseen = 0.0;
};

class BloomPass {
  public:
    // For a picture of width × height; the pyramid stops before a side would drop below 8 px.
    // Errors: RGBA16F not renderable, a shader that does not build.
    static Result<BloomPass> make(int width, int height);

    // Filters `scene` (an RGBA16F texture of the picture's size, or RGBA32F where the GL filters
    // floats: OES_texture_float_linear) into the pyramid's levels from the cut level on (the
    // smaller ones; spread() fills the wider ones' sums). `content`: the tiles where the scene
    // differs from one flat colour, which it was everywhere else the last time too (null:
    // anywhere); each level is then rewritten only where these tiles or the last run's reach
    // it. Gives the picture's tiles whose pixels may differ from the background's own once the
    // glare is mixed in: the content's, and those the content's glare reaches, or with a cut
    // only those where the glare changes the picture by more than the display shows (GlareCut),
    // read back from the cut level (so the GPU's queue drains there).
    Result<const TileSet*> run(GLuint scene, const TileSet* content = nullptr,
                               const std::optional<GlareCut>& cut = std::nullopt);
    // Fills the wider levels' sums wherever the picture's pixels in `region` read them, after
    // run(): the glare texture then holds this frame's glare there, and only there.
    Result<bool> spread(const TileSet& region);
    // The last run's content is unknown to the next (the pyramid was filled from another
    // background): it is rewritten whole.
    void forget() { damage_.forget(); }
    // The top level's sum (where spread() filled it).
    GLuint glare_texture() const;
    // The glare could not be read back to be cut (the GL reads no float texels): it is whole.
    bool cut_unavailable() const { return cut_unavailable_; }
    int levels() const { return static_cast<int>(levels_.size()); }

  private:
    struct Level {
        Texture down;  // the downsample of the level above (of the picture, for the top one)
        Framebuffer down_framebuffer;
        Texture sum;  // down + the next level's sum, upsampled; the last level has none
        Framebuffer sum_framebuffer;
        int width = 0;
        int height = 0;
    };
    BloomPass(Program down, Program up) : down_(std::move(down)), up_(std::move(up)) {}
    glm::ivec2 size_of(std::size_t level) const {
        return {levels_[level].width, levels_[level].height};
    }
    static constexpr int kMaxLevels = 6;  // at 1080p the widest blur spans a tenth of the height
    using LevelRegions = std::array<PixelRect, kMaxLevels>;
    // Each level's texels that read anything of the picture's `region`: through the filters
    // down (`down`), and then also back up from the smaller levels (`sum`).
    void level_regions(const PixelRect& region, LevelRegions& down, LevelRegions& sum) const;
    // The level whose sum is read back to cut the glare, and below which (the wider levels)
    // the sums are spread only where the picture reads them: its texels are 8 pixels, or the
    // smallest level's where there are fewer levels.
    std::size_t cut_level() const { return std::min<std::size_t>(2, levels_.size() - 1); }
    // The picture's pixels whose glare reads `from` (texels of the cut level's sum) or, through
    // the wider levels, their downsamples in `down`.
    PixelRect picture_reach(const LevelRegions& down, const PixelRect& from) const;
    // Marks on shown_ the tiles of the pixels whose glare reads a texel of the cut level's sum
    // in `region` that the display shows; false where they cannot be read.
    bool mark_shown(const PixelRect& region, const GlareCut& cut);
    // Level i's sum, down + the next level's sum upsampled, over `rects` (draw_over()).
    void draw_sum(std::size_t i, std::vector<PixelRect>& rects);
    // Draws the bound pass over `rects` of `level`: the rectangle about them all where that is
    // no larger (the smaller levels, where the tiles' reaches overlap), else the cells of
    // kLevelCell texels they touch, each once.
    void draw_over(std::vector<PixelRect>& rects, std::size_t level);
    // Each level's rectangles that `rects` (of the picture) reach, down and summed
    // (level_regions()), into down_rects_ and sum_rects_.
    void follow_rects(const std::vector<PixelRect>& rects);
    GLuint sum_texture(std::size_t level) const {
        return level + 1 == levels_.size() ? levels_[level].down.get() : levels_[level].sum.get();
    }

    Program down_;
    Program up_;
    // The first step's read of the picture: bilinear, whatever filter the picture's texture
    // has (HdrPicture's are point-sampled: its other passes fetch texels), so that each of the
    // 13 taps averages 2×2 of its pixels. Point-sampled, the taps see one pixel of each 2×2
    // block in a checkerboard, and a sparkle's glare comes and goes as it moves by a pixel
    // (GpuBloomEnergy). Fetching the 36 texels the taps average instead, each once, took
    // llvmpipe longer: 8.3 ms against the taps' 5.7 and 6.6 (the first step's mean over
    // bench_picture's frames, run in turn, 2026-12-06).
    Sampler picture_sampler_;
    std::vector<Level> levels_;
    TileDamage damage_;
    RectDraw rect_draw_;
    // Kept between frames, so that a frame allocates nothing: the tiles' rectangles, each
    // level's rectangles this pass draws, and the tiles run() gives.
    std::vector<PixelRect> tile_rects_;
    std::array<std::vector<PixelRect>, kMaxLevels> down_rects_;
    std::array<std::vector<PixelRect>, kMaxLevels> sum_rects_;
    static constexpr int kLevelCell = 8;  // texels a side of the cells a level is drawn in
    std::array<TileSet, kMaxLevels> level_cells_;
    TileSet shown_;
    std::vector<float> read_back_;  // the cut level's texels, RGBA
    bool cut_unavailable_ = false;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace gem::gpu
