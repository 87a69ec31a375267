#include "gpu/program_catalog.hpp"

namespace gem::gpu {

std::vector<ProgramSpec> all_program_specs() {
    return {
        {"background", {"fullscreen.vert"}, {"camera.glsl", "background.frag"}, {}},
        // The thesis' shading stage from ray-tables (table_method.hpp).
        {"table", {"fullscreen.vert"}, {"camera.glsl", "shading.glsl", "table.frag"}, {}},
        {"table_non_convex",
         {"fullscreen.vert"},
         {"camera.glsl", "shading.glsl", "table.frag"},
         {"NON_CONVEX"}},
        // Per-pixel tracing in the fragment shader (trace_method.hpp).
        {"trace", {"fullscreen.vert"}, {"camera.glsl", "shading.glsl", "trace.frag"}, {}},
        {"trace_non_convex",
         {"fullscreen.vert"},
         {"camera.glsl", "shading.glsl", "trace.frag"},
         {"NON_CONVEX"}},
        // The alpha-blended Phong baseline, thesis fig. 8.17 (phong_method.hpp).
        {"phong", {"phong.vert"}, {"phong.frag"}, {}},
        // The ring's metal, physically based (ring_renderer.hpp).
        {"ring", {"ring.vert"}, {"ring.frag"}, {}},
        // The kiosk's rotate-and-encode copy to the window surface (kiosk/display/present_pass).
        {"present", {"fullscreen.vert"}, {"present.frag"}, {}},
    };
}

Result<Program> build_program(const std::string& name) {
    for (const ProgramSpec& spec : all_program_specs()) {
        if (spec.name == name) return Program::build(spec);
    }
    return Error{"no GPU program named '" + name + "'"};
}

}  // namespace gem::gpu
