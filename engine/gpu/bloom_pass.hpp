#pragma once
// The glare around bright exits: a pyramid of half-size RGBA16F levels (Jimenez 2014, see
// shaders/bloom_down.frag), filtered down from the HDR picture and added back up. The top
// level then holds the sum of `levels()` ever wider blurs of the picture, each with the
// picture's energy; shaders/finish.frag mixes their mean in.
//
// Each level keeps its downsample and its sum apart (the sum is the downsample plus the wider
// level's sum, upsampled: shaders/bloom_up.frag), so that where a piece on a flat background
// changes only part of the picture, a level's downsample is redrawn only where the piece
// reaches it, and its sum only where the sums below reach it (SurfaceDamage, pixel_rect.hpp).

#include <array>
#include <optional>
#include <vector>

#include "gpu/gl_handles.hpp"
#include "gpu/pixel_rect.hpp"
#include "gpu/program.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class BloomPass {
  public:
    // For a picture of width × height; the pyramid stops before a side would drop below 8 px.
    // Errors: RGBA16F not renderable, a shader that does not build.
    static Result<BloomPass> make(int width, int height);

    // Filters `scene` (an RGBA16F texture of the picture's size, or RGBA32F where the GL filters
    // floats: OES_texture_float_linear) into the pyramid. `content`:
    // where the scene differs from one flat colour, which it was everywhere else the last time
    // too (nullopt: anywhere); each level is then rewritten only where this content or the
    // last run's reaches it. Leaves the scissor test on.
    Result<bool> run(GLuint scene, const std::optional<PixelRect>& content = std::nullopt);
    // The picture's pixels whose glare reads anything from the scene's pixels in `content`,
    // those included: where the glare of a piece on a flat background differs from the
    // background's own.
    PixelRect reach(const PixelRect& content) const;
    // The last run's content is unknown to the next (the pyramid was filled from another
    // background): it is rewritten whole.
    void forget() { damage_.forget(); }
    // The top level's sum.
    GLuint glare_texture() const;
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
    GLuint sum_texture(std::size_t level) const {
        return level + 1 == levels_.size() ? levels_[level].down.get() : levels_[level].sum.get();
    }

    Program down_;
    Program up_;
    // The first step's read of the picture: bilinear, whatever filter the picture's texture
    // has (HdrPicture's are point-sampled: its other passes fetch texels), so that each of the
    // 13 taps averages 2×2 of its pixels. Point-sampled, the taps see one pixel of each 2×2
    // block in a checkerboard, and a sparkle's glare comes and goes as it moves by a pixel
    // (GpuBloomEnergy).
    Sampler picture_sampler_;
    VertexArray empty_;
    std::vector<Level> levels_;
    SurfaceDamage damage_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace gem::gpu
