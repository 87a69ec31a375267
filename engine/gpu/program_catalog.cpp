#include "gpu/program_catalog.hpp"

#include "gpu/program_variants.hpp"
#include "gpu/stone_method.hpp"

namespace gem::gpu {

std::vector<std::string> stone_method_sources(const char* main_file) {
    return {"camera.glsl", "texel.glsl",      "stone.glsl",       "specular.glsl", "shading.glsl",
            "metal.glsl",  "piece_path.glsl", "stone_sight.glsl", main_file};
}

std::vector<ProgramSpec> all_program_specs() {
    std::vector<ProgramSpec> specs{
        {"background", {"fullscreen.vert"}, {"camera.glsl", "background.frag"}, {}},
        // The stones' depth alone, before the metal and the shading (StoneMethod::draw_depth).
        {"stone_depth", {"stone.vert"}, {"stone_depth.frag"}, {}},
        // The stones' depth with each pixel's stone and entry facet (frame_renderer.hpp).
        {"stone_visibility", {"stone.vert"}, {"stone_visibility.frag"}, {"VISIBILITY_PASS"}},
        // The metal's depth alone (RingRenderer::draw), before it is shaded where it is seen.
        {"ring_depth", {"ring.vert"}, {"stone_depth.frag"}, {}},
        // The ring's metal, physically based (ring_renderer.hpp).
        {"ring",
         {"ring.vert"},
         {"texel.glsl", "specular.glsl", "metal.glsl", "piece_path.glsl", "metal_sight.glsl",
          "ring.frag"},
         {},
         kLightCountBits | kSeesPiece | kVisibility},
        // The environment filtered by the metal's lobe (metal_environment.hpp).
        {"metal_filter", {"fullscreen.vert"}, {"metal_filter.frag"}, {}},
        // The picture from HDR radiance to the display: glare pyramid, tone curve
        // (hdr_picture.hpp, bloom_pass.hpp), each drawn over the tiles it rewrites (rect_draw.hpp).
        {"bloom_down", {"rects.vert"}, {"bloom_down.frag"}, {}},
        {"bloom_up", {"rects.vert"}, {"bloom_up.frag"}, {}},
        {"accumulate", {"rects.vert"}, {"accumulate.frag"}, {}},
        {.name = "resolve",
         .vertex = {"rects.vert"},
         .fragment = {"resolve.frag"},
         .defines = {},
         .glsl_version = "310 es"},
        {"finish", {"rects.vert"}, {"tone_map.glsl", "finish.frag"}, {}},
    };
    // Each stone method's own, listed from the registry.
    for (const MethodEntry* method : stone_methods()) {
        for (ProgramSpec& spec : method->programs()) specs.push_back(std::move(spec));
    }
    return specs;
}

Result<Program> build_program(const std::string& name, const std::vector<std::string>& defines,
                              const std::string& glsl_version) {
    for (ProgramSpec spec : all_program_specs()) {
        if (spec.name != name) continue;
        spec.defines.insert(spec.defines.end(), defines.begin(), defines.end());
        spec.glsl_version = glsl_version;
        return Program::build(spec);
    }
    return Error{"no GPU program named '" + name + "'"};
}

}  // namespace gem::gpu
