#include "reference_images.hpp"

#include "cpu/reference_render.hpp"
#include "gpu_frames.hpp"

namespace gem::accuracy {

Result<CpuFrame> render_cpu(const Scene& scene, const Environment& environment,
                            const glm::dvec3& view, int image, const ReferenceSettings& settings) {
    RenderSettings rs;
    rs.width = image;
    rs.height = image;
    rs.samples_per_pixel = settings.samples;
    rs.camera = frame_camera(scene.stone, view, image);
    rs.shading = scene_lights();
    rs.trace.max_depth = settings.depth;
    rs.trace.min_weight = settings.min_weight;
    rs.spectral = settings.spectral;
    rs.spectral_samples = 12;
    RenderStats stats;
    if (scene.ring) {
        // The stone in its ring as a piece: rays leave the stone onto the metal and back, as
        // the exact piece reference traces them. The piece frames its own bounding sphere, so
        // the zoom is scaled to keep the stone's pixel size.
        Piece piece;
        piece.name = scene.name;
        piece.kinds.push_back(scene.stone);
        piece.stones.push_back({0, {}, "centre"});
        piece.metal = *scene.ring;
        rs.camera.zoom *= piece.radius_mm() / bounding_radius(scene.stone.vertices);
        auto rendered = render_piece_reference(piece, environment, rs, &stats);
        if (!rendered) return Error{rendered.error()};
        return CpuFrame{std::move(rendered).value(), stats.seconds};
    }
    auto rendered = render_reference(scene.stone, environment, rs, &stats);
    if (!rendered) return Error{rendered.error()};
    return CpuFrame{std::move(rendered).value(), stats.seconds};
}

Result<std::vector<float>> stone_coverage(const Scene& scene, const glm::dvec3& view, int image) {
    RenderSettings rs;
    rs.width = image;
    rs.height = image;
    rs.samples_per_pixel = 1;
    rs.camera = frame_camera(scene.stone, view, image);
    rs.trace.max_depth = 1;
    auto rendered = render_reference(scene.stone, Environment::studio(), rs);
    if (!rendered) return Error{rendered.error()};
    std::vector<float> covered(rendered.value().pixels.size());
    for (std::size_t i = 0; i < covered.size(); ++i) covered[i] = rendered.value().pixels[i].w;
    return covered;
}

}  // namespace gem::accuracy
