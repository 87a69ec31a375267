#pragma once
// Fills the bound framebuffer with the background: the environment cube seen by the camera,
// or a solid colour (linear RGB), which is a clear, not a pass over every pixel.

#include <optional>

#include <glm/glm.hpp>

#include "gpu/environment_cube.hpp"
#include "gpu/program.hpp"
#include "picture/camera.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class BackgroundPass {
  public:
    static Result<BackgroundPass> make();
    // `colour` set: a solid colour (glClear, sRGB-encoded by the GL where the picture is sRGB,
    // as a fragment's output would be); otherwise the environment.
    Result<bool> draw(const Camera& camera, const EnvironmentCube& environment,
                      std::optional<glm::vec3> colour) const;

  private:
    explicit BackgroundPass(Program program);
    Program program_;
    VertexArray empty_;
};

}  // namespace gem::gpu
