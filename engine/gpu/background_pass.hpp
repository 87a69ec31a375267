#pragma once
// Fills the bound framebuffer with the background: the environment cube seen by the camera,
// or a solid colour (linear RGB).

#include <optional>

#include <glm/glm.hpp>

#include "gpu/environment_cube.hpp"
#include "gpu/program.hpp"
#include "render/camera.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class BackgroundPass {
  public:
    static Result<BackgroundPass> make();
    // `colour` set: a solid colour; otherwise the environment.
    Result<bool> draw(const Camera& camera, const EnvironmentCube& environment,
                      std::optional<glm::vec3> colour) const;

  private:
    explicit BackgroundPass(Program program);
    Program program_;
    VertexArray empty_;
};

}  // namespace gem::gpu
