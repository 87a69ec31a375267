#include "gpu/program_catalog.hpp"

#include "gpu/program_variants.hpp"

namespace gem::gpu {
namespace {

// A stone method's fragment shader: the shading, what a piece's still frames follow through
// the piece (stone_sight.glsl), then the method's own file.
std::vector<std::string> stone_sources(const char* method) {
    return {"camera.glsl", "texel.glsl",      "stone.glsl",       "specular.glsl", "shading.glsl",
            "metal.glsl",  "piece_path.glsl", "stone_sight.glsl", method};
}

}  // namespace

std::vector<ProgramSpec> all_program_specs() {
    constexpr std::uint32_t kTableFeatures = kShadingFeatures | kFireFirstOrder | kTwoViews;
    constexpr std::uint32_t kTraceFeatures =
        kShadingFeatures | kFireFirstOrder | kFireExact | kVisibility | kVisibilitySamples;
    return {
        {"background", {"fullscreen.vert"}, {"camera.glsl", "background.frag"}, {}},
        // The thesis' shading stage from ray-tables (table_method.hpp).
        // Every stone method draws the stone pass (stone.vert, stone_geometry.hpp) and reads
        // the facets from stone.glsl; each differs in its fragment shader's last file.
        // In a piece's still frames a method's exits follow the piece (stone_sight.glsl).
        {"table", {"stone.vert"}, stone_sources("table.frag"), {}, kTableFeatures},
        {"table_non_convex",
         {"stone.vert"},
         stone_sources("table.frag"),
         {"NON_CONVEX"},
         kTableFeatures},
        // Exact tracing per fragment, exits by walking the facets (trace_method.hpp).
        {"trace", {"stone.vert"}, stone_sources("trace.frag"), {}, kTraceFeatures},
        // A non-convex stone's fire is traced per channel in a still view only.
        {"trace_non_convex",
         {"stone.vert"},
         stone_sources("trace.frag"),
         {"NON_CONVEX"},
         kShadingFeatures | kFireExact | kVisibility | kVisibilitySamples},
        // The stones' depth alone, before the metal and the shading (StoneMethod::draw_depth).
        {"stone_depth", {"stone.vert"}, {"stone_depth.frag"}, {}},
        // The stones' depth with each pixel's stone and entry facet (frame_renderer.hpp).
        {"stone_visibility", {"stone.vert"}, {"stone_visibility.frag"}, {"VISIBILITY_PASS"}},
        // The metal's depth alone (RingRenderer::draw), before it is shaded where it is seen.
        {"ring_depth", {"ring.vert"}, {"stone_depth.frag"}, {}},
        // The alpha-blended Phong baseline, thesis fig. 8.17 (phong_method.hpp).
        {"phong",
         {"stone.vert"},
         {"stone.glsl", "specular.glsl", "phong.frag"},
         {},
         kLightCountBits | kSpecularPowerBits},
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
        // (hdr_picture.hpp, bloom_pass.hpp).
        {"bloom_down", {"fullscreen.vert"}, {"bloom_down.frag"}, {}},
        {"bloom_up", {"fullscreen.vert"}, {"bloom_up.frag"}, {}},
        {"accumulate", {"fullscreen.vert"}, {"accumulate.frag"}, {}},
        {"finish", {"fullscreen.vert"}, {"tone_map.glsl", "finish.frag"}, {}},
    };
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
