#pragma once
// Turns a scene description into the things a render needs: the stone, the environment and
// the render settings.

#include "geometry/stone.hpp"
#include "render/environment.hpp"
#include "render/reference_render.hpp"
#include "scene/scene.hpp"
#include "util/result.hpp"

namespace gem {

// Builds the cut (or imports the model) in the scene's material. Errors name the parameter
// or the file.
Result<Stone> build_stone(const Scene& scene);

// Loads the image for an image environment; errors name the file.
Result<Environment> build_environment(const Scene& scene);

RenderSettings render_settings(const Scene& scene);

}  // namespace gem
