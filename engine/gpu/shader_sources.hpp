#pragma once
// The GLSL ES sources of engine/gpu/shaders, built into the library (the kiosk reads no
// shader files at run time; its own passes' sources are built into kiosk/passes the same way). A
// program is linked from a list of these names: shared chunks
// (*.glsl) first, the stage's main file (*.vert, *.frag) last.

#include <string_view>
#include <vector>

namespace gem::gpu {

struct ShaderSource {
    std::string_view name;  // file name, e.g. "table.frag"
    std::string_view text;
};

const std::vector<ShaderSource>& shader_sources();

}  // namespace gem::gpu
