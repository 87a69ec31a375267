#pragma once
// The per-frame inputs every GPU stone method shares, and the uniforms they become in
// camera.glsl and shading.glsl. Lights and the environment are in the stone frame.

#include "geometry/stone.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/program.hpp"
#include "render/camera.hpp"
#include "render/shading.hpp"

namespace gem::gpu {

struct StoneFrame {
    const Stone* stone = nullptr;
    Material material;  // may differ from stone->material: colour changes without a rebuild
    Camera camera;
    ShadingSettings shading;
    const EnvironmentCube* environment = nullptr;
    double cube_half_mm = 0.0;  // the virtual cube's half side; 0 puts it at infinity
};

void set_camera_uniforms(const Program& program, const Camera& camera);
// Binds the environment cube to texture unit `unit`.
void set_shading_uniforms(const Program& program, const StoneFrame& frame, int unit);

}  // namespace gem::gpu
