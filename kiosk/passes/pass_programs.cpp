#include "passes/pass_programs.hpp"

namespace gem::kiosk {

Result<gpu::Program> build_pass_program(const std::string& name, const std::string& fragment,
                                        std::vector<std::string> defines, PassCover cover) {
    gpu::ProgramSpec spec{
        .name = name,
        .vertex = {cover == PassCover::rectangles ? "rects.vert" : "fullscreen.vert"},
        .fragment = {fragment},
        .defines = std::move(defines)};
    spec.sources = &pass_shader_sources();
    return gpu::Program::build(spec);
}

}  // namespace gem::kiosk
