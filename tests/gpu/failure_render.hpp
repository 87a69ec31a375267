#pragma once
// What the failure-mode tests (tests/gpu/failure_*_test.cpp) and the failure gallery
// (tests/bench/failure_gallery.cpp) share: one GPU scene (studio environment, two lights) that
// renders a database's stone with the table method (nearest or blend) or the trace method, and
// the exact CPU image of the same camera whose alpha says where the stone is, so stone masks
// and error maps come from one definition. Needs a current GL context; no GoogleTest here.

#include <memory>
#include <vector>

#include "gemdb/reader.hpp"
#include "gpu/background_pass.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/render_target.hpp"
#include "gpu/table_method.hpp"
#include "gpu/trace_method.hpp"
#include "picture/camera.hpp"
#include "picture/image.hpp"
#include "scene/environment.hpp"
#include "util/result.hpp"

namespace gem::failure {

// Two lights as the table-method tests use: a bright point above and a dim directional one.
ShadingSettings two_lights();

struct TableRender {
    Image image;
    gpu::TableFrameStats stats;
};

class FailureScene {
  public:
    // The table methods (nearest and blend) are made once and kept, so a path of frames
    // renders as an animation would, with the view cache warm.
    static Result<FailureScene> make(std::shared_ptr<const Database> database);
    FailureScene(FailureScene&&) noexcept;
    FailureScene& operator=(FailureScene&&) noexcept;
    ~FailureScene();

    // With `background` the environment is drawn first (alpha 1 everywhere); without it the
    // target starts transparent black and alpha is the stone's coverage.
    Result<TableRender> table(const Camera& camera, bool blend, bool background = true);
    Result<Image> trace(const Camera& camera, bool background = true);
    // The table method into an RGBA32F target (EXT_color_buffer_float), stone layer only,
    // every float as the shader wrote it (NaN and infinity survive). Errors when the GL has
    // no renderable float format.
    Result<std::vector<glm::vec4>> table_float(const Camera& camera, bool blend);
    Result<std::vector<glm::vec4>> trace_float(const Camera& camera);
    // "RGBA32F", "RGBA16F" or "none": what table_float and trace_float render into.
    static const char* float_format();

    // Exact CPU image: each pixel centre's ray traced (Camera::ray → Tracer → Shader) at the
    // database's depth and threshold; colour over the environment, alpha 1 where the ray hits
    // the stone and 0 where it misses.
    Image exact(const Camera& camera) const;

    const Database& database() const { return *database_; }
    const Stone& stone() const { return database_->stone(); }
    const Environment& environment() const { return environment_; }
    // A camera looking along `view` (stone → eye) with the database's stone size.
    Result<Camera> camera(const glm::dvec3& view, double zoom, int size) const;

  private:
    Result<gpu::RenderTarget> begin(const Camera& camera, bool background);
    FailureScene() = default;
    gpu::StoneFrame frame(const Camera& camera) const;

    std::shared_ptr<const Database> database_;
    Environment environment_;
    std::unique_ptr<gpu::EnvironmentCube> cube_;
    std::unique_ptr<gpu::BackgroundPass> background_;
    std::unique_ptr<gpu::TableMethod> nearest_;
    std::unique_ptr<gpu::TableMethod> blend_;
    std::unique_ptr<gpu::TraceMethod> trace_;
};

// View geometry, by brute force so that paths and bounds do not rest on ViewGrid's search.
double angle_between(const glm::dvec3& a, const glm::dvec3& b);  // radians, any lengths
// Every symmetric image h·s of every stored view s: the directions whose tables exist.
std::vector<glm::dvec3> stored_images(const ViewGrid& grid);
std::size_t nearest_index(const std::vector<glm::dvec3>& images, const glm::dvec3& d);
// The stored image nearest to stored view `view` other than itself.
std::size_t nearest_neighbour(const std::vector<glm::dvec3>& images, const glm::dvec3& view);
// Along the great circle from unit a to unit b, t in [0, 1].
glm::dvec3 slerp(const glm::dvec3& a, const glm::dvec3& b, double t);

// Linear-light luminance (Rec. 709 / sRGB primaries, IEC 61966-2-1).
float luminance(const glm::vec4& c);

// Images side by side with a 2-pixel gap, for the gallery and failure artefacts.
Image side_by_side(const std::vector<Image>& images);

}  // namespace gem::failure
