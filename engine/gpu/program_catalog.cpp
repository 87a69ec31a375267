#include "gpu/program_catalog.hpp"

namespace gem::gpu {

std::vector<ProgramSpec> all_program_specs() {
    return {
        {"background", {"fullscreen.vert"}, {"camera.glsl", "background.frag"}, {}},
    };
}

Result<Program> build_program(const std::string& name) {
    for (const ProgramSpec& spec : all_program_specs()) {
        if (spec.name == name) return Program::build(spec);
    }
    return Error{"no GPU program named '" + name + "'"};
}

}  // namespace gem::gpu
