#include "still_pictures.hpp"

#include <optional>

#include "gpu/frame_composer.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/hdr_picture.hpp"
#include "gpu/render_target.hpp"
#include "gpu_frames.hpp"
#include "picture/tone_map.hpp"
#include "reference_images.hpp"

namespace gem::accuracy {
namespace {

struct StillPoint {
    gpu::TraceDispersion fire;
    int frames;  // 1: the moving picture
    int depth;   // the still frames' depth
};

// The moving frames' depth, the sweep's base trace and the kiosk's render.depth.
constexpr int kMovingDepth = 8;
constexpr int kStillFrames = 16;  // the kiosk's picture.still_frames

}  // namespace

Result<bool> still_rows(const Scene& scene, const Environment& environment, const glm::dvec3& view,
                        const std::vector<float>& mask, int image, bool quick,
                        std::vector<Row>& rows) {
    ReferenceSettings averaged = full_reference();
    averaged.samples = 16;
    auto reference = render_cpu(scene, environment, view, image, averaged);
    if (!reference) return Error{reference.error()};
    // The picture is read after its tone curve (no glare): the reference goes through the same.
    const Image shown_reference = to_display(reference.value().image, {});

    std::vector<StillPoint> points = {{gpu::TraceDispersion::exact, 1, kMovingDepth},
                                      {gpu::TraceDispersion::exact, kStillFrames, kMovingDepth}};
    for (const int depth : quick ? std::vector<int>{8, 16} : std::vector<int>{8, 16, 32}) {
        points.push_back({gpu::TraceDispersion::spectral, kStillFrames, depth});
    }
    const CameraSettings camera = frame_camera(scene.stone, view, image);
    auto target = gpu::RenderTarget::make(image, image);
    if (!target) return Error{target.error()};
    // One renderer per fire (the points come grouped by it): making one times the stone's
    // exit searches and builds its programs.
    std::optional<gpu::FrameRenderer> renderer;
    gpu::TraceDispersion renderer_fire = gpu::TraceDispersion::none;
    for (const StillPoint& p : points) {
        if (!renderer || renderer_fire != p.fire) {
            gpu::FrameSetup setup;
            setup.method = "trace";
            setup.stone = scene.stone;
            setup.material = scene.stone.material;
            setup.shading = scene_lights();
            setup.trace.max_depth = kMovingDepth;
            setup.trace_dispersion = p.fire;
            setup.environment = &environment;
            auto made = gpu::FrameRenderer::make(std::move(setup));
            if (!made) return Error{made.error()};
            renderer.emplace(std::move(made).value());
            renderer_fire = p.fire;
        }
        auto picture = gpu::HdrPicture::make(image, image,
                                             {.samples = 4,
                                              .display = {},
                                              .glare = 0.0,
                                              .still_frames = p.frames,
                                              .spectral = p.fire == gpu::TraceDispersion::spectral,
                                              .still_depth = p.depth});
        if (!picture) return Error{picture.error()};
        // The programs' first use is not the still picture's cost.
        const gpu::FrameView frame_view{.camera = camera,
                                        .framing_mm = renderer->stone_radius_mm()};
        picture.value().begin_frame(false);
        auto warm = gpu::compose_frame({.renderer = &*renderer,
                                        .view = frame_view,
                                        .wait = gpu::FrameWait::frame,
                                        .picture = &picture.value()},
                                       target.value());
        if (!warm) return Error{warm.error()};
        if (auto drawn = warm.value().scene(); !drawn) return Error{drawn.error()};
        double ms = 0.0;
        auto drawn =
            gpu::draw_still_picture(*renderer, picture.value(), frame_view, target.value(), &ms);
        if (!drawn) return Error{drawn.error()};
        Row row;
        row.study = "still";
        row.scene = scene.name;
        row.view = "on";
        row.method = "trace";
        row.depth = p.depth;
        row.threshold = TraceSettings{}.min_weight;
        row.dispersion = p.fire == gpu::TraceDispersion::spectral;
        row.samples = p.frames;
        row.compared_with = "ref-16spp";
        row.frame_ms = ms;
        auto e = stone_error(target.value().read(), shown_reference, mask);
        if (!e) return Error{e.error()};
        row.error = e.value();
        print_row(row);
        rows.push_back(std::move(row));
    }
    return true;
}

}  // namespace gem::accuracy
