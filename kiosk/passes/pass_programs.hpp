#pragma once
// The kiosk's own passes' programs (the present pass, the cross-fade): their fragment shaders
// live in kiosk/passes/shaders, built into this library as the engine builds its own
// (cmake/embed_shaders.cmake); their vertex shaders are the engine's.

#include <string>
#include <vector>

#include "gpu/program.hpp"
#include "gpu/shader_sources.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

const std::vector<gpu::ShaderSource>& pass_shader_sources();

// A pass of `fragment` from kiosk/passes/shaders: full-screen (the engine's fullscreen.vert), or
// over some rectangles of its target (rects.vert, gpu/rect_draw.hpp).
enum class PassCover { full_screen, rectangles };
Result<gpu::Program> build_pass_program(const std::string& name, const std::string& fragment,
                                        std::vector<std::string> defines = {},
                                        PassCover cover = PassCover::full_screen);

}  // namespace gem::kiosk
