#pragma once
// The kiosk's own passes' programs (the present pass, the cross-fade): their fragment shaders
// live in kiosk/passes/shaders, built into this library as the engine builds its own
// (cmake/embed_shaders.cmake); the full-screen triangle's vertex shader is the engine's.

#include <string>
#include <vector>

#include "gpu/program.hpp"
#include "gpu/shader_sources.hpp"
#include "util/result.hpp"

namespace gem::kiosk {

const std::vector<gpu::ShaderSource>& pass_shader_sources();

// A full-screen pass: the engine's fullscreen.vert and `fragment` from kiosk/passes/shaders.
Result<gpu::Program> build_pass_program(const std::string& name, const std::string& fragment,
                                        std::vector<std::string> defines = {});

}  // namespace gem::kiosk
