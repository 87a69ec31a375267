#pragma once
// The CPU reference render's settings for a scene description (scene/scene.hpp): its picture,
// camera, shading and trace.

#include "cpu/reference_render.hpp"
#include "scene/scene.hpp"

namespace gem {

RenderSettings render_settings(const Scene& scene);

}  // namespace gem
