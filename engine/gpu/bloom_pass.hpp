#pragma once
// The glare around bright exits: a pyramid of half-size RGBA16F levels (Jimenez 2014, see
// shaders/bloom_down.frag), filtered down from the HDR picture and added back up. The top
// level then holds the sum of `levels()` ever wider blurs of the picture, each with the
// picture's energy; shaders/finish.frag mixes their mean in.

#include <vector>

#include "gpu/gl_handles.hpp"
#include "gpu/program.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class BloomPass {
  public:
    // For a picture of width × height; the pyramid stops before a side would drop below 8 px.
    // Errors: RGBA16F not renderable, a shader that does not build.
    static Result<BloomPass> make(int width, int height);

    // Filters `scene` (an RGBA16F texture of the picture's size) into the pyramid.
    Result<bool> run(GLuint scene);
    GLuint glare_texture() const { return levels_.front().texture.get(); }
    int levels() const { return static_cast<int>(levels_.size()); }

  private:
    struct Level {
        Texture texture;
        Framebuffer framebuffer;
        int width = 0;
        int height = 0;
    };
    BloomPass(Program down, Program up) : down_(std::move(down)), up_(std::move(up)) {}

    Program down_;
    Program up_;
    VertexArray empty_;
    std::vector<Level> levels_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace gem::gpu
