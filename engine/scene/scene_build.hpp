#pragma once
// Turns a scene description into the things a render needs: the stone and the environment
// (the CPU reference render's settings: cpu/scene_settings.hpp).

#include "geometry/stone.hpp"
#include "scene/environment.hpp"
#include "scene/scene.hpp"
#include "util/result.hpp"

namespace gem {

// Builds the cut (or imports the model) in the scene's material. Errors name the parameter
// or the file.
Result<Stone> build_stone(const Scene& scene);

// Loads the image for an image environment; errors name the file.
Result<Environment> build_environment(const Scene& scene);

}  // namespace gem
