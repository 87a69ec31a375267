#include "gpu_frames.hpp"

#include <algorithm>

#include "gpu/environment_cube.hpp"
#include "gpu/frame_composer.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/render_target.hpp"
#include "gpu/ring_renderer.hpp"
#include "gpu/trace_method.hpp"
#include "view_trace.hpp"

namespace gem::accuracy {

CameraSettings frame_camera(const Stone& stone, const glm::dvec3& view, int image) {
    const glm::dvec3 v = glm::normalize(view);
    CameraSettings s;
    s.azimuth_deg = glm::degrees(std::atan2(v.x, v.z));
    s.elevation_deg = glm::degrees(std::asin(std::clamp(v.y, -1.0, 1.0)));
    // Camera::make sizes pixels as 2R / (zoom · side); a stored view's pixel is field / side.
    const double radius = bounding_radius(stone.vertices);
    s.zoom = 2.0 * radius / tables::table_camera(stone).field_mm;
    (void)image;  // the same zoom at every image size: the image side is the level it matches
    return s;
}

Result<std::vector<GpuFrame>> render_gpu(const Scene& scene, const Environment& environment,
                                         const GpuPoint& point,
                                         const std::vector<glm::dvec3>& views, int image,
                                         int frames) {
    gpu::FrameSetup setup;
    setup.method = point.method;
    setup.database = point.database;
    setup.stone = scene.stone;
    setup.material = scene.stone.material;
    setup.shading = scene_lights();
    // The baseline draws the stone with opacity 1 − α (phong.frag); α = 1, the physical
    // model's value, would leave it invisible. 0.8 is gemrender's default scene.
    if (point.method == "phong") setup.shading.alpha = 0.8;
    setup.trace = point.trace;
    setup.table.blend = point.blend;
    setup.table.wait_for_views = true;
    setup.environment = &environment;
    if (scene.ring) setup.ring = &*scene.ring;
    auto renderer = gpu::FrameRenderer::make(std::move(setup));
    if (!renderer) return Error{renderer.error()};
    auto target = gpu::RenderTarget::make(image, image);
    if (!target) return Error{target.error()};
    std::vector<GpuFrame> out;
    for (const glm::dvec3& view : views) {
        // The stone method's own pixels, straight into the target (no picture to finish).
        const gpu::FrameRequest request{
            .renderer = &renderer.value(),
            .view = gpu::FrameView{.camera = frame_camera(scene.stone, view, image),
                                   .framing_mm = renderer.value().stone_radius_mm(),
                                   .wait_for_views = true},
            .wait = gpu::FrameWait::frame};
        GpuFrame frame;
        std::vector<double> ms;
        for (int f = -1; f < frames; ++f) {  // frame −1: program, textures, first decode
            auto composed = gpu::compose_frame(request, target.value());
            if (!composed) return Error{composed.error()};
            auto stats = composed.value().scene();
            if (!stats) return Error{stats.error()};
            if (f < 0) continue;
            ms.push_back(stats.value().cpu_ms);
            frame.table = stats.value().table;
        }
        std::sort(ms.begin(), ms.end());
        frame.median_ms = ms[ms.size() / 2];
        frame.image = target.value().read();
        out.push_back(std::move(frame));
    }
    return out;
}

Result<std::vector<float>> ring_coverage(const Scene& scene, const Environment& environment,
                                         const glm::dvec3& view, int image) {
    std::vector<float> none(static_cast<std::size_t>(image) * image, 0.0f);
    if (!scene.ring) return none;
    // The stone layer writes its entry depth (trace method); the colour is then cleared, the
    // depth kept, and the ring drawn: what the ring leaves in alpha is where it is in front.
    auto cube = gpu::EnvironmentCube::from_environment(environment, 64);
    if (!cube) return Error{cube.error()};
    auto trace = gpu::TraceMethod::make(scene.stone);
    if (!trace) return Error{trace.error()};
    auto ring = gpu::RingRenderer::make(*scene.ring, cube.value());
    if (!ring) return Error{ring.error()};
    auto target = gpu::RenderTarget::make(image, image);
    if (!target) return Error{target.error()};
    target.value().bind();
    const double radius = bounding_radius(scene.stone.vertices);
    const double scene_radius = std::max(radius, scene.ring->radius_mm()) * 1.01;
    auto camera = Camera::make(frame_camera(scene.stone, view, image), radius, image, image);
    if (!camera) return Error{camera.error()};
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepthf(1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const gpu::StoneFrame frame{&scene.stone,   scene.stone.material, camera.value(),
                                scene_lights(), &cube.value(),        scene.ring->radius_mm(),
                                scene_radius};
    auto drawn = trace.value().draw(frame, TraceSettings{});
    if (!drawn) return Error{drawn.error()};
    glClear(GL_COLOR_BUFFER_BIT);
    drawn = ring.value().draw(camera.value(), scene_radius, scene_lights());
    if (!drawn) return Error{drawn.error()};
    auto ok = gpu::gl_check("ring coverage");
    if (!ok) return Error{ok.error()};
    const Image read = target.value().read();
    for (std::size_t i = 0; i < none.size(); ++i) none[i] = read.pixels[i].w > 0.5f ? 1.0f : 0.0f;
    return none;
}

}  // namespace gem::accuracy
