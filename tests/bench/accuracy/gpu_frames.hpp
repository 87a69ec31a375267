#pragma once
// GPU frames of the sweep: one FrameRenderer per method and setting (as gemrender and the
// kiosk draw), timed as the median of a few glFinish-bounded frames after a warm-up frame,
// and read back as a linear image. Also the ring's share of a ring scene's pixels, which the
// CPU reference (no ring geometry) cannot be compared on.

#include <memory>
#include <vector>

#include "gemdb/reader.hpp"
#include "gpu/frame_renderer.hpp"
#include "gpu/table_method.hpp"
#include "picture/camera.hpp"
#include "picture/image.hpp"
#include "scene/environment.hpp"
#include "scenes.hpp"
#include "trace/tracer.hpp"
#include "util/result.hpp"

namespace gem::accuracy {

// The camera settings of a scene's frame: orthographic along `view`, zoomed so that one
// screen pixel is one pixel of a stored view of side `image` (table_aligned_camera in the
// GPU tests): a level equal to `image` is a table at screen resolution.
CameraSettings frame_camera(const Stone& stone, const glm::dvec3& view, int image);

struct GpuPoint {
    std::string method = "table";
    std::shared_ptr<const Database> database;  // table only
    bool blend = false;                        // table: two nearest views
    TraceSettings trace;                       // trace only: depth and threshold
};

struct GpuFrame {
    Image image;
    double median_ms = 0.0;
    gpu::TableFrameStats table;  // the last timed frame's (table method)
};

// For each of `views`: `frames` timed frames (after one warm-up) of `scene` seen along it,
// from one renderer (program, cubes and the view cache made once).
Result<std::vector<GpuFrame>> render_gpu(const Scene& scene, const Environment& environment,
                                         const GpuPoint& point,
                                         const std::vector<glm::dvec3>& views, int image,
                                         int frames);

// 1 where the ring is drawn in front of the stone or the background, else 0 (row-major).
Result<std::vector<float>> ring_coverage(const Scene& scene, const Environment& environment,
                                         const glm::dvec3& view, int image);

}  // namespace gem::accuracy
