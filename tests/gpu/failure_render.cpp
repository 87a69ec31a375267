#include "failure_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "gpu/gl_check.hpp"
#include "gpu/gl_handles.hpp"
#include "gpu/render_target.hpp"
#include "scene/shading.hpp"
#include "trace/tracer.hpp"
#include "view_trace.hpp"

namespace gem::failure {
namespace {

constexpr int kCubeFace = 512;

bool has_extension(const char* name) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto* ext = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (ext != nullptr && std::strcmp(ext, name) == 0) return true;
    }
    return false;
}

// An RGBA32F colour target with depth, cleared to transparent black. The stone pass blends
// (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), which a 32-bit float target allows only with
// EXT_float_blend; without it the half-float format (blendable in ES 3.2) is used.
struct FloatTarget {
    gpu::Framebuffer framebuffer;
    gpu::Texture colour;
    gpu::Renderbuffer depth;
};

Result<FloatTarget> make_float_target(int width, int height) {
    if (!has_extension("GL_EXT_color_buffer_float")) {
        return Error{"float target: GL_EXT_color_buffer_float is missing"};
    }
    FloatTarget t;
    t.colour = gpu::make_texture();
    glBindTexture(GL_TEXTURE_2D, t.colour.get());
    const GLenum format = has_extension("GL_EXT_float_blend") ? GL_RGBA32F : GL_RGBA16F;
    glTexStorage2D(GL_TEXTURE_2D, 1, format, width, height);
    t.depth = gpu::make_renderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, t.depth.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    t.framebuffer = gpu::make_framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.colour.get(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth.get());
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        return Error{"float target: framebuffer incomplete"};
    }
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    auto ok = gpu::gl_check("float target");
    if (!ok) return Error{ok.error()};
    return t;
}

std::vector<glm::vec4> read_float(int width, int height) {
    std::vector<glm::vec4> out(static_cast<std::size_t>(width) * height);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, out.data());
    return out;  // bottom row first; the tests only look at values
}

}  // namespace

ShadingSettings two_lights() {
    ShadingSettings s;
    s.lights = {{{30.0, 80.0, 40.0}, false, {3.0, 3.0, 3.0}},
                {{-1.0, 1.0, -0.5}, true, {1.0, 0.9, 0.8}}};
    return s;
}

FailureScene::FailureScene(FailureScene&&) noexcept = default;
FailureScene& FailureScene::operator=(FailureScene&&) noexcept = default;
FailureScene::~FailureScene() = default;

Result<FailureScene> FailureScene::make(std::shared_ptr<const Database> database) {
    FailureScene s;
    s.database_ = std::move(database);
    s.environment_ = Environment::studio();
    auto cube = gpu::EnvironmentCube::from_environment(s.environment_, kCubeFace);
    if (!cube) return Error{cube.error()};
    s.cube_ = std::make_unique<gpu::EnvironmentCube>(std::move(cube).value());
    auto background = gpu::BackgroundPass::make();
    if (!background) return Error{background.error()};
    s.background_ = std::make_unique<gpu::BackgroundPass>(std::move(background).value());
    for (const bool blend : {false, true}) {
        gpu::TableOptions options;
        options.blend = blend;
        options.wait_for_views = true;
        auto method = gpu::TableMethod::make(s.database_, options);
        if (!method) return Error{method.error()};
        (blend ? s.blend_ : s.nearest_) =
            std::make_unique<gpu::TableMethod>(std::move(method).value());
    }
    auto trace = gpu::TraceMethod::make(s.database_->stone());
    if (!trace) return Error{trace.error()};
    s.trace_ = std::make_unique<gpu::TraceMethod>(std::move(trace).value());
    return s;
}

gpu::StoneFrame FailureScene::frame(const Camera& camera) const {
    return {&stone(), stone().material, camera, two_lights(), cube_.get(), 0.0, 10.0};
}

Result<Camera> FailureScene::camera(const glm::dvec3& view, double zoom, int size) const {
    const glm::dvec3 v = glm::normalize(view);
    CameraSettings s;
    s.azimuth_deg = glm::degrees(std::atan2(v.x, v.z));
    s.elevation_deg = glm::degrees(std::asin(std::clamp(v.y, -1.0, 1.0)));
    s.zoom = zoom;
    return Camera::make(s, bounding_radius(stone().vertices), size, size);
}

// A bound, cleared target of the camera's size, with the environment drawn when asked.
Result<gpu::RenderTarget> FailureScene::begin(const Camera& camera, bool background) {
    auto target = gpu::RenderTarget::make(camera.width(), camera.height());
    if (!target) return Error{target.error()};
    target.value().bind();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (background) {
        auto drawn = background_->draw(camera, *cube_, std::nullopt);
        if (!drawn) return Error{drawn.error()};
    }
    return target;
}

Result<TableRender> FailureScene::table(const Camera& camera, bool blend, bool background) {
    auto target = begin(camera, background);
    if (!target) return Error{target.error()};
    TableRender out;
    auto drawn = (blend ? blend_ : nearest_)->draw(frame(camera), &out.stats);
    if (!drawn) return Error{drawn.error()};
    out.image = target.value().read();
    return out;
}

Result<Image> FailureScene::trace(const Camera& camera, bool background) {
    auto target = begin(camera, background);
    if (!target) return Error{target.error()};
    auto drawn = trace_->draw(frame(camera), tables::table_trace_settings(database_->params()));
    if (!drawn) return Error{drawn.error()};
    return target.value().read();
}

const char* FailureScene::float_format() {
    if (!has_extension("GL_EXT_color_buffer_float")) return "none";
    return has_extension("GL_EXT_float_blend") ? "RGBA32F" : "RGBA16F";
}

Result<std::vector<glm::vec4>> FailureScene::table_float(const Camera& camera, bool blend) {
    auto target = make_float_target(camera.width(), camera.height());
    if (!target) return Error{target.error()};
    auto drawn = (blend ? blend_ : nearest_)->draw(frame(camera));
    if (!drawn) return Error{drawn.error()};
    return read_float(camera.width(), camera.height());
}

Result<std::vector<glm::vec4>> FailureScene::trace_float(const Camera& camera) {
    auto target = make_float_target(camera.width(), camera.height());
    if (!target) return Error{target.error()};
    auto drawn = trace_->draw(frame(camera), tables::table_trace_settings(database_->params()));
    if (!drawn) return Error{drawn.error()};
    return read_float(camera.width(), camera.height());
}

Image FailureScene::exact(const Camera& camera) const {
    const gpu::StoneFrame f = frame(camera);
    const Tracer tracer(stone());
    const Shader shader(stone(), f.material, environment_, f.shading);
    const TraceSettings settings = tables::table_trace_settings(database_->params());
    const glm::vec3 background(environment_.radiance(camera.forward()));
    Image out(camera.width(), camera.height());
    RayList list;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            tracer.trace(camera.ray(x + 0.5, y + 0.5), f.material.index(), settings, list);
            out.at(x, y) = list.hit ? glm::vec4(glm::vec3(shader.shade(list)), 1.0f)
                                    : glm::vec4(background, 0.0f);
        }
    }
    return out;
}

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

std::vector<glm::dvec3> stored_images(const ViewGrid& grid) {
    std::vector<glm::dvec3> out;
    for (const glm::dvec3& s : grid.directions()) {
        for (const glm::dmat3& h : grid.group()) out.push_back(h * s);
    }
    return out;
}

std::size_t nearest_index(const std::vector<glm::dvec3>& images, const glm::dvec3& d) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < images.size(); ++i) {
        if (angle_between(images[i], d) < angle_between(images[best], d)) best = i;
    }
    return best;
}

std::size_t nearest_neighbour(const std::vector<glm::dvec3>& images, const glm::dvec3& view) {
    std::size_t best = images.size();
    for (std::size_t i = 0; i < images.size(); ++i) {
        if (angle_between(images[i], view) < 1e-6) continue;
        if (best == images.size() ||
            angle_between(images[i], view) < angle_between(images[best], view)) {
            best = i;
        }
    }
    return best;
}

glm::dvec3 slerp(const glm::dvec3& a, const glm::dvec3& b, double t) {
    const double omega = angle_between(a, b);
    return (std::sin((1.0 - t) * omega) * a + std::sin(t * omega) * b) / std::sin(omega);
}

float luminance(const glm::vec4& c) {
    return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

Image side_by_side(const std::vector<Image>& images) {
    constexpr int kGap = 2;
    int width = 0;
    int height = 0;
    for (const Image& image : images) {
        width += image.width + (width > 0 ? kGap : 0);
        height = std::max(height, image.height);
    }
    Image out(width, height, glm::vec4(1.0f));
    int x0 = 0;
    for (const Image& image : images) {
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                out.at(x0 + x, y) = glm::vec4(glm::vec3(image.at(x, y)), 1.0f);
            }
        }
        x0 += image.width + kGap;
    }
    return out;
}

}  // namespace gem::failure
