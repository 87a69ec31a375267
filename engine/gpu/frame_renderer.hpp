#pragma once
// One frame of the shading stage, whatever the method: background, stone layer (table,
// trace or phong: a loose stone, or every stone of a piece), ring or the piece's metal,
// composited with alpha and depth into the bound framebuffer (docs/design.md, "Data flow").
// gemrender and the kiosk both draw through it. With metal, the virtual cube shows it around
// the stones: its six faces are rendered from the centre (the loose stone's, the piece's) when
// the scene changes (make() and set_lights()), not every frame.

#include <memory>
#include <optional>

#include "gpu/background_pass.hpp"
#include "gpu/environment_cube.hpp"
#include "gpu/frame_uniforms.hpp"
#include "gpu/table_method.hpp"
#include "gpu/trace_method.hpp"
#include "piece/metal_mesh.hpp"
#include "piece/piece.hpp"
#include "render/environment.hpp"
#include "trace/tracer.hpp"
#include "util/result.hpp"

namespace gem::gpu {

class PhongMethod;
class RingRenderer;

enum class Method { table, trace, phong };
const char* to_string(Method method);

struct FrameSetup {
    Method method = Method::table;
    std::shared_ptr<const Database> database;  // table: the stone comes from it
    Stone stone;                               // trace, phong (ignored by table)
    Material material;                         // shading-time material (colour, absorption)
    ShadingSettings shading;
    TraceSettings trace;  // trace: depth, weights, threshold
    TraceDispersion trace_dispersion = TraceDispersion::none;
    TableOptions table;
    // What surrounds everything; must outlive the renderer (an orthographic frame's background
    // is its radiance along the view).
    const Environment* environment = nullptr;
    int cube_face = 512;                         // virtual-cube face size, texels
    std::optional<glm::vec3> background_colour;  // else the environment shows behind
    const MetalMesh* ring = nullptr;             // optional jewellery around the stone
    // trace, phong: a whole piece instead of `stone` and `ring`: every stone drawn in its own
    // frame (identical stones share their method's programs and stone block), the piece's
    // metal around them. Must outlive the renderer.
    const Piece* piece = nullptr;
};

// How one kind of stone is traced: the depth followed and how fire is coloured. The frame
// renderer starts every kind at the setup's (FrameSetup::trace, trace_dispersion); a piece's
// small stones may be given less (stone_models.hpp chooses it by measurement).
struct StoneModel {
    int depth = 8;
    TraceDispersion fire = TraceDispersion::none;
    bool operator==(const StoneModel&) const = default;
};

// What render() waits for: nothing (a display's swap paces it), the whole frame (timing), or
// each pass too (benchmarks: the stone pass timed alone; the extra waits cost time).
enum class FrameWait { none, frame, passes };

struct FrameStats {
    double cpu_ms = 0.0;  // from the start of the frame to glFinish returning
    // The stone pass alone, between a glFinish after the background and one after the stone
    // (FrameWait::passes only; 0 otherwise): what the method costs, without the picture's
    // other passes.
    double stone_ms = 0.0;
    double metal_ms = 0.0;  // the ring's or piece's metal pass alone, as stone_ms
    TableFrameStats table;
};

class FrameRenderer {
  public:
    static Result<FrameRenderer> make(FrameSetup setup);
    FrameRenderer(FrameRenderer&&) noexcept;
    FrameRenderer& operator=(FrameRenderer&&) noexcept;
    ~FrameRenderer();

    // Draws into the bound framebuffer (viewport set), waiting for the GPU as `wait` says.
    Result<FrameStats> render(const Camera& camera, FrameWait wait);
    // New lights re-render the ring's cube faces (its metal reflects them).
    Result<bool> set_lights(const std::vector<Light>& lights);

    Method method() const { return setup_.method; }
    // The stone (a piece's centre stone).
    const Stone& stone() const;

    // The kinds of stone drawn (a piece's distinct stones; one for a loose stone), each traced
    // with its own model (trace only; the other methods have none).
    std::size_t kind_count() const { return models_.size(); }
    const Stone& kind(std::size_t k) const;
    // The stones drawn (a loose stone: one), each of a kind, placed in the piece.
    std::size_t stone_count() const { return kinds_.size(); }
    std::size_t kind_of(std::size_t stone) const { return kinds_[stone]; }
    const Placement& placement_of(std::size_t stone) const { return frames_[stone].placement; }
    // The first stone of kind `k` (its placement, material).
    std::size_t first_of_kind(std::size_t k) const;
    const StoneModel& model(std::size_t k) const { return models_[k]; }
    void set_model(std::size_t k, const StoneModel& model);
    // Draws the first stone of kind `k` alone, loose at the centre with its material, as
    // `model` traces it, into the bound framebuffer (viewport set; depth cleared first), seeing
    // what the piece's stones see: for measuring a model (stone_models.hpp). Trace only.
    Result<bool> draw_kind_alone(std::size_t k, const Camera& camera, const StoneModel& model);
    // Radius about the centre (the stone's, the piece's) that holds everything drawn.
    double scene_radius_mm() const { return scene_radius_mm_; }
    double stone_radius_mm() const { return stone_radius_mm_; }
    TableMethod* table() { return table_.get(); }
    // The trace of the (centre) stone.
    const TraceMethod* trace() const { return trace_.empty() ? nullptr : trace_.front().get(); }

  private:
    FrameRenderer() = default;
    Result<bool> update_ring_cube();

    FrameSetup setup_;
    std::unique_ptr<BackgroundPass> background_;
    std::unique_ptr<EnvironmentCube> environment_cube_;  // the environment alone
    std::unique_ptr<EnvironmentCube> ring_cube_;         // environment + ring, from the centre
    // The stones drawn, each a frame made once (its material, placement and shading; the camera
    // and cube are filled in per frame, so a frame copies nothing that allocates), and its kind
    // (the method below).
    std::vector<StoneFrame> frames_;
    std::vector<std::size_t> kinds_;
    std::vector<StoneModel> models_;         // per kind
    std::vector<TraceSettings> kind_trace_;  // per kind: the setup's, at its model's depth
    std::unique_ptr<TableMethod> table_;
    std::vector<std::unique_ptr<TraceMethod>> trace_;  // one per kind of stone
    std::vector<std::unique_ptr<PhongMethod>> phong_;  // one per kind of stone
    std::unique_ptr<RingRenderer> ring_;
    double scene_radius_mm_ = 0.0;
    double stone_radius_mm_ = 0.0;
    double cube_half_mm_ = 0.0;
};

}  // namespace gem::gpu
