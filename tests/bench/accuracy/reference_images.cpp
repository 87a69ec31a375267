#include "reference_images.hpp"

#include <cmath>
#include <numbers>

#include "gpu/environment_cube.hpp"
#include "gpu/gl_check.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/ring_renderer.hpp"
#include "gpu_frames.hpp"
#include "render/reference_render.hpp"

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
    auto rendered = render_reference(scene.stone, environment, rs, &stats);
    if (!rendered) return Error{rendered.error()};
    return CpuFrame{std::move(rendered).value(), stats.seconds};
}

namespace {

constexpr int kCubeFace = 512;
constexpr int kEquirectWidth = 2048;

// The six faces of `cube` as linear RGB, face-major, row t = 0 first (the face's first row
// in memory, as cube_face_direction counts it).
Result<std::vector<glm::vec4>> read_cube(const gpu::EnvironmentCube& cube) {
    const int n = cube.face_size();
    std::vector<glm::vec4> texels(static_cast<std::size_t>(6) * n * n);
    gpu::Framebuffer fb = gpu::make_framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, fb.get());
    for (int face = 0; face < 6; ++face) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                               GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, cube.texture(), 0);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            return Error{"ring environment: cannot read back the virtual cube"};
        }
        glReadPixels(0, 0, n, n, GL_RGBA, GL_FLOAT,
                     texels.data() + static_cast<std::size_t>(face) * n * n);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    auto ok = gpu::gl_check("ring environment: read back");
    if (!ok) return Error{ok.error()};
    return texels;
}

// Nearest texel of the read-back cube toward unit direction d.
glm::vec3 cube_lookup(const std::vector<glm::vec4>& texels, int n, const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    const int face = a.x >= a.y && a.x >= a.z ? (d.x > 0 ? 0 : 1)
                     : a.y >= a.z             ? (d.y > 0 ? 2 : 3)
                                              : (d.z > 0 ? 4 : 5);
    // cube_face_direction is centre + sc·right + tc·up before normalising; invert it.
    const glm::dvec3 c = gpu::cube_face_direction(face, 0.5, 0.5);
    const glm::dvec3 r = gpu::cube_face_direction(face, 1.0, 0.5) * std::sqrt(2.0) - c;
    const glm::dvec3 u = gpu::cube_face_direction(face, 0.5, 1.0) * std::sqrt(2.0) - c;
    const glm::dvec3 p = d / glm::dot(d, c);
    const double s = (glm::dot(p, r) + 1.0) / 2.0;
    const double t = (glm::dot(p, u) + 1.0) / 2.0;
    const int x = std::clamp(static_cast<int>(s * n), 0, n - 1);
    const int y = std::clamp(static_cast<int>(t * n), 0, n - 1);
    return glm::vec3(texels[(static_cast<std::size_t>(face) * n + y) * n + x]);
}

}  // namespace

Result<Environment> scene_environment(const Scene& scene, const Environment& studio) {
    if (!scene.ring) return studio;
    auto background = gpu::EnvironmentCube::from_environment(studio, kCubeFace);
    if (!background) return Error{background.error()};
    auto cube = gpu::EnvironmentCube::allocate(kCubeFace);
    if (!cube) return Error{cube.error()};
    auto ring = gpu::RingRenderer::make(*scene.ring);
    if (!ring) return Error{ring.error()};
    auto drawn =
        ring.value().render_environment_cube(background.value(), cube.value(), scene_lights());
    if (!drawn) return Error{drawn.error()};
    auto texels = read_cube(cube.value());
    if (!texels) return Error{texels.error()};
    // Equirectangular as Environment::image_radiance reads it: column u = atan2(x, −z)/2π + ½,
    // row v = acos(y)/π, texel centres at half-integers.
    const int w = kEquirectWidth;
    const int h = kEquirectWidth / 2;
    std::vector<glm::vec3> pixels(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y) {
        const double theta = (y + 0.5) / h * std::numbers::pi;
        for (int x = 0; x < w; ++x) {
            const double lon = ((x + 0.5) / w - 0.5) * 2.0 * std::numbers::pi;
            const glm::dvec3 d(std::sin(theta) * std::sin(lon), std::cos(theta),
                               -std::sin(theta) * std::cos(lon));
            pixels[static_cast<std::size_t>(y) * w + x] = cube_lookup(texels.value(), kCubeFace, d);
        }
    }
    return Environment::from_pixels(w, h, std::move(pixels));
}

}  // namespace gem::accuracy
